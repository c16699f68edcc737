// fbm speed against libnoise (Debian libnoise-dev) in the same run: 2D
// gradient fbm, 2048^2 samples x 8 octaves. Counters per sample per octave:
// wall_ns (wall time) and cpu_ns (CPU time of the whole process, all
// threads): on a busy shared machine cpu_ns is the steadier figure, wall_ns
// is what a user waits for. The speed-up is the ratio to libnoise's.
//   build/native/noise_bench
#include <benchmark/benchmark.h>
#include <libnoise/noise.h>

#include <chrono>
#include <ctime>
#include <vector>

#include "noise/fbm.hpp"
#include "terrain/spectral_synthesis.hpp"

namespace {

constexpr int kOctaves = 8;

double process_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

// Times each iteration's body by wall clock and by process CPU clock.
class Timer {
 public:
  template <class F>
  void run(F&& body) {
    const auto w0 = std::chrono::steady_clock::now();
    const double c0 = process_cpu_seconds();
    body();
    cpu_ += process_cpu_seconds() - c0;
    wall_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count();
  }
  void report(benchmark::State& state, double samples, int octaves) const {
    const double n = samples * octaves * double(state.iterations());
    state.counters["wall_ns"] = 1e9 * wall_ / n;
    state.counters["cpu_ns"] = 1e9 * cpu_ / n;
  }

 private:
  double wall_ = 0, cpu_ = 0;
};

// libnoise's Perlin module (3D gradient noise, evaluated on the z = 0 plane;
// it has no 2D variant), octave loop included, single-threaded as shipped.
void BM_LibnoisePerlin(benchmark::State& state) {
  const int n = int(state.range(0));
  noise::module::Perlin perlin;
  perlin.SetOctaveCount(kOctaves);
  perlin.SetFrequency(4.0);
  perlin.SetSeed(1);
  std::vector<float> out(size_t(n) * n);
  Timer timer;
  for (auto _ : state) {
    timer.run([&] {
      for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x)
          out[size_t(y) * n + x] = float(perlin.GetValue(double(x) / n, double(y) / n, 0.0));
    });
    benchmark::DoNotOptimize(out.data());
  }
  timer.report(state, double(n) * n, kOctaves);
}

// fracterra gradient fbm; range(1) = threads (0: all cores), range(2) = 1 to
// force the x86-64 baseline path instead of AVX2.
void BM_FracterraFbm(benchmark::State& state) {
  ft::noise::FbmConfig c;
  c.width = c.height = int(state.range(0));
  c.octaves = kOctaves;
  c.basis = int(state.range(3));
  c.threads = int(state.range(1));
  ft::noise::detail::set_simd_path(state.range(2) ? ft::noise::detail::SimdPath::kBaseline : ft::noise::detail::SimdPath::kAuto);
  state.SetLabel(ft::noise::detail::active_simd_path());
  Timer timer;
  for (auto _ : state) {
    timer.run([&] {
      ft::Heightfield hf = ft::noise::fbm(c);
      benchmark::DoNotOptimize(hf.data());
    });
  }
  ft::noise::detail::set_simd_path(ft::noise::detail::SimdPath::kAuto);
  timer.report(state, double(c.width) * c.height, kOctaves);
}

void BM_SpectralSynthesis(benchmark::State& state) {
  ft::terrain::SpectralConfig c;
  c.width = c.height = int(state.range(0));
  Timer timer;
  for (auto _ : state) {
    timer.run([&] {
      ft::Heightfield hf = ft::terrain::spectral_synthesis(c);
      benchmark::DoNotOptimize(hf.data());
    });
  }
  timer.report(state, double(c.width) * c.height, 1);
}

BENCHMARK(BM_LibnoisePerlin)->Arg(2048)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(2);
// args: size, threads, baseline, basis
BENCHMARK(BM_FracterraFbm)
    ->Args({2048, 0, 0, ft::noise::kBasisGradient})
    ->Args({2048, 1, 0, ft::noise::kBasisGradient})
    ->Args({2048, 0, 1, ft::noise::kBasisGradient})
    ->Args({2048, 0, 0, ft::noise::kBasisValue})
    ->Args({2048, 0, 0, ft::noise::kBasisSimplex})
    ->Args({2048, 0, 0, ft::noise::kBasisCellularF1})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_SpectralSynthesis)->Arg(2048)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
