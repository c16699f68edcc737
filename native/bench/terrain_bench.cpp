// SPDX-License-Identifier: GPL-3.0-or-later
// Midpoint displacement at 1025^2, 4097^2 and 8193^2: fracterra against a
// naive sequential diamond-square (std::mt19937 + std::normal_distribution,
// as most tutorials write it), in the same run. Windows: a 4097^2 tile of a
// 65537^2 terrain (the tile sets' task) against a standalone 4097^2 terrain,
// one thread each (the target: at most 1.3x).
//   build/native/terrain_bench --benchmark_min_time=0.5
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

#include "terrain/terrain.hpp"

namespace {

// The baseline: the textbook loops of MidPointFM2D, one thread.
std::vector<float> naive_midpoint(int levels, double hurst, unsigned seed) {
  const int n = 1 << levels, w = n + 1;
  std::vector<float> x(size_t(w) * w);
  std::mt19937 rng(seed);
  std::normal_distribution<float> gauss(0.0f, 1.0f);
  auto at = [&](int i, int j) -> float& { return x[size_t(j) * w + i]; };
  double delta = 1.0;
  at(0, 0) = float(delta * gauss(rng));
  at(n, 0) = float(delta * gauss(rng));
  at(0, n) = float(delta * gauss(rng));
  at(n, n) = float(delta * gauss(rng));
  for (int big = n, half = n / 2; half >= 1; big = half, half /= 2) {
    delta *= std::pow(0.5, 0.5 * hurst);
    for (int j = half; j < n; j += big)
      for (int i = half; i < n; i += big)
        at(i, j) = 0.25f * (at(i - half, j - half) + at(i + half, j - half) + at(i - half, j + half) +
                            at(i + half, j + half)) + float(delta) * gauss(rng);
    delta *= std::pow(0.5, 0.5 * hurst);
    for (int j = 0; j <= n; j += half)
      for (int i = (j / half) % 2 ? 0 : half; i <= n; i += big) {
        float sum = 0;
        int k = 0;
        if (i >= half) sum += at(i - half, j), ++k;
        if (i + half <= n) sum += at(i + half, j), ++k;
        if (j >= half) sum += at(i, j - half), ++k;
        if (j + half <= n) sum += at(i, j + half), ++k;
        at(i, j) = sum / float(k) + float(delta) * gauss(rng);
      }
  }
  return x;
}

void BM_NaiveMidpoint(benchmark::State& state) {
  const int levels = int(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(naive_midpoint(levels, 0.8, 1).data());
  const double side = double((1 << levels) + 1);
  state.counters["samples/s"] = benchmark::Counter(side * side, benchmark::Counter::kIsIterationInvariantRate);
}

void BM_FracterraMidpoint(benchmark::State& state) {
  ft_terrain_params p = ft::terrain::default_terrain_params();
  p.levels = int(state.range(0));
  p.hurst = 0.8;
  p.threads = int(state.range(1));
  for (auto _ : state) {
    ft::Heightfield hf = ft::terrain::generate_terrain(p);
    benchmark::DoNotOptimize(hf.data());
  }
  const double side = double((1 << p.levels) + 1);
  state.counters["samples/s"] = benchmark::Counter(side * side, benchmark::Counter::kIsIterationInvariantRate);
}

// A tile of a levels-16 terrain (65537^2, never whole): the window of
// tile (7, 9) of `fracterra tiles --tile 4096`, halo included.
void BM_MidpointWindow(benchmark::State& state) {
  ft_terrain_params p = ft::terrain::default_terrain_params();
  p.levels = 16;
  p.hurst = 0.8;
  p.threads = int(state.range(0));
  for (auto _ : state) {
    ft::Heightfield hf = ft::terrain::generate_terrain_window(p, 0, 7 * 4096, 9 * 4096, 4097, 4097);
    benchmark::DoNotOptimize(hf.data());
  }
  state.counters["samples/s"] = benchmark::Counter(4097.0 * 4097.0, benchmark::Counter::kIsIterationInvariantRate);
}

BENCHMARK(BM_NaiveMidpoint)->Arg(10)->Arg(12)->Arg(13)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_FracterraMidpoint)
    ->Args({10, 1})->Args({10, 0})->Args({12, 1})->Args({12, 0})->Args({13, 1})->Args({13, 0})
    ->ArgNames({"levels", "threads"})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_MidpointWindow)->Arg(1)->Arg(0)->ArgNames({"threads"})->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
