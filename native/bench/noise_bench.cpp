// fbm speed against libnoise (Debian libnoise-dev) in the same run: 2D
// gradient fbm, 2048^2 samples x 8 octaves. The counter ns_per_sample_octave
// is wall time / (samples x octaves); the ratio of the two is the speed-up.
//   build/native/noise_bench --benchmark_filter=2048
#include <benchmark/benchmark.h>
#include <libnoise/noise.h>

#include <vector>

#include "noise/fbm.hpp"
#include "terrain/spectral_synthesis.hpp"

namespace {

constexpr int kOctaves = 8;

void set_counter(benchmark::State& state, double samples, int octaves) {
  state.counters["ns_per_sample_octave"] = benchmark::Counter(
      samples * octaves * 1e-9, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

// libnoise's Perlin module (3D gradient noise, evaluated on the z = 0 plane;
// it has no 2D variant), octave loop included, single-threaded as shipped.
void BM_LibnoisePerlin(benchmark::State& state) {
  const int n = int(state.range(0));
  noise::module::Perlin perlin;
  perlin.SetOctaveCount(kOctaves);
  perlin.SetFrequency(4.0);
  perlin.SetSeed(1);
  std::vector<float> out(size_t(n) * n);
  for (auto _ : state) {
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x)
        out[size_t(y) * n + x] = float(perlin.GetValue(double(x) / n, double(y) / n, 0.0));
    benchmark::DoNotOptimize(out.data());
  }
  set_counter(state, double(n) * n, kOctaves);
}

// fracterra gradient fbm; range(1) = threads (0: all cores), range(2) = 1 to
// force the x86-64 baseline path instead of AVX2.
void BM_FracterraFbm(benchmark::State& state) {
  ft::FbmConfig c;
  c.width = c.height = int(state.range(0));
  c.octaves = kOctaves;
  c.basis = int(state.range(3));
  c.threads = int(state.range(1));
  ft::detail::set_simd_path(state.range(2) ? ft::detail::SimdPath::kBaseline : ft::detail::SimdPath::kAuto);
  state.SetLabel(ft::detail::active_simd_path());
  for (auto _ : state) {
    ft::Heightfield hf = ft::fbm(c);
    benchmark::DoNotOptimize(hf.data());
  }
  ft::detail::set_simd_path(ft::detail::SimdPath::kAuto);
  set_counter(state, double(c.width) * c.height, kOctaves);
}

void BM_SpectralSynthesis(benchmark::State& state) {
  ft::SpectralConfig c;
  c.width = c.height = int(state.range(0));
  for (auto _ : state) {
    ft::Heightfield hf = ft::spectral_synthesis(c);
    benchmark::DoNotOptimize(hf.data());
  }
  set_counter(state, double(c.width) * c.height, 1);
}

BENCHMARK(BM_LibnoisePerlin)->Arg(2048)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(2);
// args: size, threads, baseline, basis
BENCHMARK(BM_FracterraFbm)
    ->Args({2048, 0, 0, FT_BASIS_GRADIENT})
    ->Args({2048, 1, 0, FT_BASIS_GRADIENT})
    ->Args({2048, 0, 1, FT_BASIS_GRADIENT})
    ->Args({2048, 0, 0, FT_BASIS_VALUE})
    ->Args({2048, 0, 0, FT_BASIS_SIMPLEX})
    ->Args({2048, 0, 0, FT_BASIS_CELLULAR_F1})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_SpectralSynthesis)->Arg(2048)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
