// SPDX-License-Identifier: GPL-3.0-or-later
// Counter-based Gaussian variates: fracterra's vectorised Philox + Box-Muller
// on each dispatch path, against std::mt19937 + std::normal_distribution.
//   build/native/rng_bench
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "core/rng.hpp"

namespace {

constexpr size_t kCount = 1 << 16;

void BM_StdNormalDistribution(benchmark::State& state) {
  std::vector<float> out(kCount);
  std::mt19937 rng(1);
  std::normal_distribution<float> gauss;
  for (auto _ : state) {
    for (float& v : out) v = gauss(rng);
    benchmark::DoNotOptimize(out.data());
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * kCount);
}

void BM_GaussianFill(benchmark::State& state) {
  std::vector<float> out(kCount);
  const auto path = ft::detail::RngPath(state.range(0));
  if (!ft::detail::rng_path_available(path)) return state.SkipWithError("not on this CPU");
  for (auto _ : state) {
    ft::detail::gaussian_fill_on_path(path, 1, ft::Counter{1, 2, ft::Stream::kFirstUser}, 0, kCount, out.data());
    benchmark::DoNotOptimize(out.data());
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * kCount);
}

// Philox alone (the uniform fill's share of the Gaussian fill's time).
void BM_UniformFill(benchmark::State& state) {
  std::vector<float> out(kCount);
  const auto path = ft::detail::RngPath(state.range(0));
  if (!ft::detail::rng_path_available(path)) return state.SkipWithError("not on this CPU");
  for (auto _ : state) {
    ft::detail::uniform_fill_on_path(path, 1, ft::Counter{1, 2, ft::Stream::kFirstUser}, 0, kCount, out.data());
    benchmark::DoNotOptimize(out.data());
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * kCount);
}

BENCHMARK(BM_StdNormalDistribution);
BENCHMARK(BM_GaussianFill)->Arg(0)->Arg(1)->Arg(2)->ArgName("path");  // baseline, avx2, avx512
BENCHMARK(BM_UniformFill)->Arg(0)->Arg(1)->Arg(2)->ArgName("path");

}  // namespace

BENCHMARK_MAIN();
