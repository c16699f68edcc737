// SPDX-License-Identifier: GPL-3.0-or-later
// Erosion speed (issue 15).
//   AntPasses/N   A.N.T.'s eroder defaults done by ours on the same grid: 30
//                 hydraulic passes, 5 diffusion passes, 5 thermal passes and
//                 the maps. The grids are A.N.T.'s own landscapes, saved by
//                 native/bench/ant_eroder_anchor.py (run it first; it also
//                 times A.N.T.'s eroder on them): FT_ANT_DIR=DIR/ant_N.npy.
//                 Without them an fBm terrain of the same size stands in.
//   Fluvial/N     stream power + diffusion, 10 time steps (FT_STEPS=100 for the 100).
//   Fastscapelib/N  the baseline of Fluvial/N (issue 40; needs
//                 -DFT_FASTSCAPELIB_DIR): fastscapelib's own step, as its
//                 mountain example runs it (uplift, single-flow routing with
//                 its MST sink resolver, drainage area, stream power, ADI
//                 diffusion), FT_STEPS steps on the same grid and parameters.
//                 fastscapelib is single-threaded: compare with FT_BENCH_THREADS=1 too.
//   LandPreset/N  issue 24: the "land" preset (Rugged Mountains, the
//                 landscape model at its default strength) on an fBm terrain
//                 10 world units across, no maps: `erode --preset land`.
// Run: FT_ANT_DIR=/tmp/ant build/native/erosion_bench --benchmark_repetitions=3
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>
#include <omp.h>
#include <string>
#include <vector>

#include "erosion/erosion.hpp"
#include "erosion/presets.hpp"
#include "io/heightfield_io.hpp"
#include "terrain/terrain.hpp"

#ifdef FT_HAVE_FASTSCAPELIB
#include "fastscapelib/eroders/diffusion_adi.hpp"
#include "fastscapelib/eroders/spl.hpp"
#include "fastscapelib/flow/flow_graph.hpp"
#include "fastscapelib/flow/flow_router.hpp"
#include "fastscapelib/flow/sink_resolver.hpp"
#include "fastscapelib/grid/raster_grid.hpp"
#include "xtensor/xarray.hpp"
#include "xtensor/xview.hpp"
#endif

namespace {

using namespace ft::erosion;

int bench_steps() { return std::getenv("FT_STEPS") ? std::atoi(std::getenv("FT_STEPS")) : 10; }

int bench_threads() {
  const char* t = std::getenv("FT_BENCH_THREADS");
  return t ? std::atoi(t) : 2;
}

ft::Heightfield grid(int32_t n) {
  const char* dir = std::getenv("FT_ANT_DIR");
  const std::string path = dir ? std::string(dir) + "/ant_" + std::to_string(n) + ".npy" : "";
  if (!path.empty() && std::filesystem::exists(path)) {
    ft::Heightfield hf = ft::io::read_heightfield(path);
    hf.set_world_size(2.0);  // A.N.T.'s default mesh size
    return hf;
  }
  ft_terrain_params p = ft::terrain::default_terrain_params();
  p.method = FT_TERRAIN_FBM;
  p.width = p.height = n;
  return ft::terrain::generate_terrain(p);
}

void AntPasses(benchmark::State& state) {
  const ft::Heightfield src = grid(int32_t(state.range(0)));
  const D8Grid g = grid_of(src, false);
  ErosionConfig c;
  c.hydraulic.iterations = 30;
  c.thermal.iterations = 5;
  c.threads = bench_threads();
  omp_set_num_threads(c.threads);  // for the diffusion passes, outside erode()
  for (auto _ : state) {
    ErosionMaps maps;
    ft::Heightfield out = erode(src, c, &maps);
    for (int k = 0; k < 5; ++k) hillslope_diffusion(g, out.data(), c.fluvial.diffusion * c.fluvial.dt);
    benchmark::DoNotOptimize(out.data());
  }
  state.counters["cells"] = double(src.size());
}
BENCHMARK(AntPasses)->Arg(257)->Arg(513)->Arg(1025)->Unit(benchmark::kMillisecond)->UseRealTime();

// The parts of AntPasses on their own (which one to work on).
void AntHydraulic(benchmark::State& state) {
  const ft::Heightfield src = grid(int32_t(state.range(0)));
  const D8Grid g = grid_of(src, false);
  HydraulicConfig c;
  c.iterations = 30;
  omp_set_num_threads(bench_threads());
  for (auto _ : state) {
    std::vector<float> out(src.data(), src.data() + src.size());
    hydraulic(g, out.data(), c, nullptr, nullptr, ft::Progress());
    benchmark::DoNotOptimize(out.data());
  }
}
BENCHMARK(AntHydraulic)->Arg(513)->Arg(1025)->Unit(benchmark::kMillisecond)->UseRealTime();

void AntMaps(benchmark::State& state) {
  const ft::Heightfield src = grid(int32_t(state.range(0)));
  ErosionConfig c;
  c.thermal.iterations = 1;
  c.threads = bench_threads();
  for (auto _ : state) {
    ErosionMaps maps;
    benchmark::DoNotOptimize(erode(src, c, &maps).data());
  }
}
BENCHMARK(AntMaps)->Arg(513)->Unit(benchmark::kMillisecond)->UseRealTime();

void Fluvial(benchmark::State& state) {
  const ft::Heightfield src = grid(int32_t(state.range(0)));
  ErosionConfig c;
  c.fluvial.steps = bench_steps();
  c.fluvial.uplift = 1e-4;
  c.threads = bench_threads();
  for (auto _ : state) benchmark::DoNotOptimize(erode(src, c, nullptr).data());
  state.counters["steps"] = c.fluvial.steps;
}
BENCHMARK(Fluvial)->Arg(513)->Arg(1025)->Arg(2049)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

#ifdef FT_HAVE_FASTSCAPELIB
// fastscapelib's step on Fluvial's grid with Fluvial's parameters (K, m,
// n = 1, D, uplift, dt; the edge fixed): its doc/source/examples/mountain.cpp
// loop. Double precision, its own containers; only the steps are timed.
void Fastscapelib(benchmark::State& state) {
  namespace fs = fastscapelib;
  const ft::Heightfield src = grid(int32_t(state.range(0)));
  const FluvialConfig f;
  const auto n = size_t(src.width());
  const double spacing = grid_of(src, false).spacing;
  const int steps = bench_steps();
  xt::xarray<double> start = xt::empty<double>({n, n});
  std::copy(src.data(), src.data() + src.size(), start.begin());
  for (auto _ : state) {
    state.PauseTiming();
    xt::xarray<double> z = start;
    state.ResumeTiming();
    auto g = fs::raster_grid({{n, n}}, {spacing, spacing}, fs::node_status::fixed_value);
    fs::flow_graph<fs::raster_grid> graph(g, {fs::single_flow_router(), fs::mst_sink_resolver()});
    auto spl = fs::make_spl_eroder(graph, f.erodibility, f.area_exponent, 1.0, 1e-5);
    auto diffusion = fs::diffusion_adi_eroder(g, f.diffusion);
    xt::xarray<double> uplift = xt::full_like(z, 1e-4 * f.dt);
    xt::view(uplift, xt::keep(0, -1), xt::all()) = 0.0;
    xt::view(uplift, xt::all(), xt::keep(0, -1)) = 0.0;
    xt::xarray<double> area(z.shape()), lifted(z.shape());
    for (int s = 0; s < steps; ++s) {
      lifted = z + uplift;
      graph.update_routes(lifted);
      graph.accumulate(area, 1.0);
      auto spl_erosion = spl.erode(lifted, area, f.dt);
      auto diff_erosion = diffusion.erode(lifted - spl_erosion, f.dt);
      z = lifted - spl_erosion - diff_erosion;
    }
    benchmark::DoNotOptimize(z.data());
  }
  state.counters["steps"] = steps;
}
BENCHMARK(Fastscapelib)->Arg(513)->Arg(1025)->Arg(2049)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);
#endif

void LandPreset(benchmark::State& state) {
  ft_terrain_params p = ft::terrain::default_terrain_params();
  p.method = FT_TERRAIN_FBM;
  p.width = p.height = int32_t(state.range(0));
  p.hurst = 0.8;
  p.seed = 1;
  ft::Heightfield src = ft::terrain::generate_terrain(p);
  src.set_world_size(10.0);
  ErosionConfig c = erosion_preset("land", src);
  c.threads = bench_threads();
  for (auto _ : state) benchmark::DoNotOptimize(erode(src, c, nullptr).data());
}
BENCHMARK(LandPreset)->Arg(513)->Arg(1025)->Arg(2049)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
