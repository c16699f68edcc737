// SPDX-License-Identifier: GPL-3.0-or-later
// fbm speed against libnoise (Debian libnoise-dev) and FastNoise2 in the
// same run: 2D fbm, 2048^2 samples x 8 octaves. Counters per sample per
// octave: wall_ns (wall time) and cpu_ns (CPU time of the whole process,
// all threads): on a busy shared machine cpu_ns is the steadier figure,
// wall_ns is what a user waits for. The speed-up is the ratio of times.
//   build/native/noise_bench --benchmark_repetitions=7 --benchmark_enable_random_interleaving=true
//
// FastNoise2 (Auburn/FastNoise2 v1.1.1, its SIMD dispatch picking the CPU's
// widest set) is a baseline only, built outside the project and found by
// -DFT_FASTNOISE2_DIR=<its install prefix> (docs/measurements/speed.md says
// how); without it its rows are skipped with the reason.
#include <benchmark/benchmark.h>
#include <libnoise/noise.h>

#include <chrono>
#include <ctime>
#include <thread>
#include <vector>

#ifdef FT_HAVE_FASTNOISE2
#include <FastNoise/FastNoise.h>
#endif

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

// The same fbm into one buffer filled again and again (fbm_window_into), as
// FastNoise2's GenUniformGrid2D fills its caller's buffer below: the
// like-for-like pair. BM_FracterraFbm also pays for a fresh heightfield per
// call, whose pages the kernel zeroes (about 10% of a 2048^2 call here).
void BM_FracterraFbmInto(benchmark::State& state) {
  ft::noise::FbmConfig c;
  c.width = c.height = int(state.range(0));
  c.octaves = kOctaves;
  c.basis = int(state.range(2));
  c.threads = int(state.range(1));
  ft::noise::validate_fbm(c);
  state.SetLabel(ft::noise::detail::active_simd_path());
  std::vector<float> out(size_t(c.width) * size_t(c.height));
  Timer timer;
  for (auto _ : state) {
    timer.run([&] { ft::noise::fbm_window_into(c, 0, 0, c.width, c.height, out.data()); });
    benchmark::DoNotOptimize(out.data());
  }
  timer.report(state, double(c.width) * c.height, kOctaves);
}

// FastNoise2's FractalFBm over the generator named like fracterra's basis
// (Perlin for gradient, Value, Simplex, CellularDistance for cellular F1),
// 8 octaves, lacunarity 2, gain 0.5, through GenUniformGrid2D with the same
// cells across the width as fracterra's default frequency (4). FastNoise2
// itself is single-threaded: with 2 threads each takes half the rows, as a
// caller would split it. range(0) = size, range(1) = threads, range(2) = basis.
void BM_FastNoise2Fbm(benchmark::State& state) {
#ifdef FT_HAVE_FASTNOISE2
  const int n = int(state.range(0)), threads = int(state.range(1));
  FastNoise::SmartNode<> source;
  switch (state.range(2)) {
    case ft::noise::kBasisValue: source = FastNoise::New<FastNoise::Value>(); break;
    case ft::noise::kBasisSimplex: source = FastNoise::New<FastNoise::Simplex>(); break;
    case ft::noise::kBasisCellularF1: {  // F1 as a distance, as fracterra's (FastNoise2's default is squared)
      auto cellular = FastNoise::New<FastNoise::CellularDistance>();
      cellular->SetDistanceFunction(FastNoise::DistanceFunction::Euclidean);
      source = cellular;
      break;
    }
    default: source = FastNoise::New<FastNoise::Perlin>(); break;
  }
  auto fbm = FastNoise::New<FastNoise::FractalFBm>();
  fbm->SetSource(source);
  fbm->SetOctaveCount(kOctaves);
  fbm->SetLacunarity(2.0f);
  fbm->SetGain(0.5f);
  std::vector<float> out(size_t(n) * n);
  const float step = 4.0f / float(n);
  auto rows = [&](int y0, int y1) {
    fbm->GenUniformGrid2D(out.data() + size_t(y0) * n, 0.0f, float(y0) * step, n, y1 - y0, step, step, 1);
  };
  Timer timer;
  for (auto _ : state) {
    timer.run([&] {
      if (threads <= 1) {
        rows(0, n);
      } else {
        std::vector<std::thread> pool;
        for (int t = 0; t < threads; ++t) pool.emplace_back(rows, n * t / threads, n * (t + 1) / threads);
        for (std::thread& th : pool) th.join();
      }
    });
    benchmark::DoNotOptimize(out.data());
  }
  timer.report(state, double(n) * n, kOctaves);
#else
  state.SkipWithError("FastNoise2 not built in: configure with -DFT_FASTNOISE2_DIR=<its install prefix> "
                      "(docs/measurements/speed.md)");
  for (auto _ : state) {
  }
#endif
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
    ->Args({2048, 2, 0, ft::noise::kBasisGradient})
    ->Args({2048, 1, 0, ft::noise::kBasisGradient})
    ->Args({2048, 2, 1, ft::noise::kBasisGradient})
    ->Args({2048, 1, 0, ft::noise::kBasisValue})
    ->Args({2048, 1, 0, ft::noise::kBasisSimplex})
    ->Args({2048, 1, 0, ft::noise::kBasisCellularF1})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
// args: size, threads, basis: the sizes, threads and bases that fracterra's
// fBm into a caller's buffer and FastNoise2's are measured at, alike.
void like_for_like(benchmark::internal::Benchmark* b) {
  b->Args({2048, 2, ft::noise::kBasisGradient})
      ->Args({2048, 1, ft::noise::kBasisGradient})
      ->Args({2048, 1, ft::noise::kBasisValue})
      ->Args({2048, 1, ft::noise::kBasisSimplex})
      ->Args({2048, 1, ft::noise::kBasisCellularF1})
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime();
}
BENCHMARK(BM_FracterraFbmInto)->Apply(like_for_like);
BENCHMARK(BM_FastNoise2Fbm)->Apply(like_for_like);
BENCHMARK(BM_SpectralSynthesis)->Arg(2048)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
