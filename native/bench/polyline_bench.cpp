// SPDX-License-Identifier: GPL-3.0-or-later
// FPL generation speed: the library's blocked breadth-first fill of a
// 2^20-segment FPL against the printed recursion appending every vertex to a
// std::vector (the baseline), and against memcpy / a plain store of the same
// number of bytes, to see whether generation is memory-bound.
//   build/native/polyline_bench --benchmark_min_time=0.5
#include <benchmark/benchmark.h>

#include <cstring>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "polyline/fpl.hpp"
#include "polyline/polyline.hpp"

namespace {

constexpr int kDepth = 20;
constexpr size_t kVertices = (size_t(1) << kDepth) + 1;

// FPLrec as printed: L grows by one push_back per vertex; the same
// position-keyed uniform draws as the library (one Philox block per draw).
void naive_rec(std::vector<ft::Vec3>& L, const ft::Vec3& b, double s, int r, int level, uint64_t j, uint64_t seed) {
  const ft::Vec3 a = L.back();
  const double vx = b[0] - a[0], vy = b[1] - a[1];
  if (r == 0) {
    L.push_back(b);
    return;
  }
  const ft::Counter k{0, uint32_t(level), ft::Stream::kPolyline};
  const double f = s * (2.0 * double(ft::bits_to_unit_open(ft::random_bits(seed, k, j))) - 1.0);
  const ft::Vec3 d{a[0] + 0.5 * vx - f * vy, a[1] + 0.5 * vy + f * vx, a[2] + 0.5 * (b[2] - a[2])};
  naive_rec(L, d, s, r - 1, level + 1, 2 * j, seed);
  naive_rec(L, b, s, r - 1, level + 1, 2 * j + 1, seed);
}

void BM_FplNaiveRecursionPushBack(benchmark::State& state) {
  for (auto _ : state) {
    std::vector<ft::Vec3> L{{0, 0, 0}};
    naive_rec(L, {1, 0, 0}, 0.2, kDepth, 0, 0, 1);
    benchmark::DoNotOptimize(L.data());
  }
  state.SetBytesProcessed(int64_t(state.iterations()) * int64_t(kVertices * sizeof(ft::Vec3)));
}
BENCHMARK(BM_FplNaiveRecursionPushBack)->Unit(benchmark::kMillisecond);

void BM_FplBlockedFill(benchmark::State& state) {
  ft::polyline::FplConfig c;
  c.depth = kDepth;
  c.spread = 0.2;
  c.rng = state.range(0) ? ft::polyline::FplRng::kNormal : ft::polyline::FplRng::kUniform;
  c.threads = int(state.range(1));
  std::vector<ft::Vec3> out(kVertices);
  for (auto _ : state) {
    ft::polyline::fpl_segment(c, {0, 0, 0}, {1, 0, 0}, 0, out.data());
    benchmark::DoNotOptimize(out.data());
  }
  state.SetBytesProcessed(int64_t(state.iterations()) * int64_t(kVertices * sizeof(ft::Vec3)));
  state.SetLabel(std::string(state.range(0) ? "normal" : "uniform") + ", threads " + std::to_string(state.range(1)));
}
// Args: {normal?, threads}; CPU time is summed over threads, so compare the
// wall time ("Time") of the 2-thread runs.
BENCHMARK(BM_FplBlockedFill)->Args({0, 1})->Args({1, 1})->Args({0, 2})->Args({1, 2})->Unit(benchmark::kMillisecond)->UseRealTime();

// The whole public path: validation, PolylineSet allocation (zero-filled by
// std::vector), radii, the fill.
void BM_FplGeneratePolylines(benchmark::State& state) {
  ft_polyline_params p = ft::polyline::default_polyline_params();
  p.depth = kDepth;
  p.spread = 0.2;
  p.threads = 1;
  for (auto _ : state) {
    ft::PolylineSet s = ft::polyline::generate_polylines(p);
    benchmark::DoNotOptimize(s.points.data());
  }
  state.SetBytesProcessed(int64_t(state.iterations()) * int64_t(kVertices * sizeof(ft::Vec3)));
}
BENCHMARK(BM_FplGeneratePolylines)->Unit(benchmark::kMillisecond);

// Memory-bound references over the same 24 MiB of vertices.
void BM_MemcpyVertices(benchmark::State& state) {
  std::vector<ft::Vec3> src(kVertices, ft::Vec3{1, 2, 3}), dst(kVertices);
  for (auto _ : state) {
    std::memcpy(dst.data(), src.data(), kVertices * sizeof(ft::Vec3));
    benchmark::DoNotOptimize(dst.data());
  }
  state.SetBytesProcessed(int64_t(state.iterations()) * int64_t(kVertices * sizeof(ft::Vec3)));
}
BENCHMARK(BM_MemcpyVertices)->Unit(benchmark::kMillisecond);

void BM_StoreVertices(benchmark::State& state) {
  std::vector<ft::Vec3> dst(kVertices);
  double x = 0;
  for (auto _ : state) {
    for (size_t i = 0; i < kVertices; ++i) dst[i] = {x, x + 1, 0};
    x += 1;
    benchmark::DoNotOptimize(dst.data());
  }
  state.SetBytesProcessed(int64_t(state.iterations()) * int64_t(kVertices * sizeof(ft::Vec3)));
}
BENCHMARK(BM_StoreVertices)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
