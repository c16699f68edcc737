// SPDX-License-Identifier: GPL-3.0-or-later
// Erosion speed (issue 15).
//   AntPasses/N   A.N.T.'s eroder defaults done by ours on the same grid: 30
//                 hydraulic passes, 5 diffusion passes, 5 thermal passes and
//                 the maps. The grids are A.N.T.'s own landscapes, saved by
//                 native/bench/ant_eroder_anchor.py (run it first; it also
//                 times A.N.T.'s eroder on them): FT_ANT_DIR=DIR/ant_N.npy.
//                 Without them an fBm terrain of the same size stands in.
//   Fluvial/N     stream power + diffusion, 10 time steps (FT_STEPS=100 for the 100).
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

namespace {

using namespace ft::erosion;

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
  c.fluvial.steps = std::getenv("FT_STEPS") ? std::atoi(std::getenv("FT_STEPS")) : 10;
  c.fluvial.uplift = 1e-4;
  c.threads = bench_threads();
  for (auto _ : state) benchmark::DoNotOptimize(erode(src, c, nullptr).data());
  state.counters["steps"] = c.fluvial.steps;
}
BENCHMARK(Fluvial)->Arg(513)->Arg(1025)->Arg(2049)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

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
