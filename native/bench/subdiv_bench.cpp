// SPDX-License-Identifier: GPL-3.0-or-later
// Fractalization against its baseline in the same run: plain OpenSubdiv
// uniform refinement + primvar interpolation of the same mesh to the same
// level (what any consumer of OpenSubdiv pays to get a refined mesh out),
// for a cube under Catmull-Clark (9 levels, 1.57M quads) and an icosahedron
// under Loop (8 levels, 1.31M triangles). Target: fractalize <= 2x baseline.
//
//   build/native/subdiv_bench --benchmark_min_time=1
#include <benchmark/benchmark.h>
#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>

#include <cstring>
#include <filesystem>
#include <memory>
#include <vector>

#include "io/obj_io.hpp"
#include "subdiv/fractalize.hpp"

namespace {

using namespace OpenSubdiv;

const std::string kMeshes =
    (std::filesystem::path(__FILE__).parent_path() / "../../examples/meshes/").lexically_normal().string();

struct Case {
  const char* file;
  int scheme;
  int levels;
};
const Case kCases[] = {{"cube.obj", FT_SCHEME_CATMARK, 9}, {"icosahedron.obj", FT_SCHEME_LOOP, 8}};

struct V {
  float p[3];
  void Clear(void* = nullptr) { p[0] = p[1] = p[2] = 0; }
  void AddWithWeight(const V& s, float w) {
    for (int i = 0; i < 3; ++i) p[i] += w * s.p[i];
  }
};

// The baseline: refine, interpolate positions level by level, copy the last
// level's faces out (fractalize returns them too).
void BM_PlainOpenSubdiv(benchmark::State& state) {
  const Case& c = kCases[state.range(0)];
  const ft::Mesh m = ft::io::read_obj(kMeshes + c.file);
  size_t faces = 0;
  for (auto _ : state) {
    Sdc::Options o;
    o.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER);
    Far::TopologyDescriptor d;
    d.numVertices = int(m.vertex_count());
    d.numFaces = int(m.face_count());
    d.numVertsPerFace = m.face_sizes.data();
    d.vertIndicesPerFace = m.face_indices.data();
    using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
    std::unique_ptr<Far::TopologyRefiner> r(Factory::Create(
        d, Factory::Options(c.scheme == FT_SCHEME_LOOP ? Sdc::SCHEME_LOOP : Sdc::SCHEME_CATMARK, o)));
    r->RefineUniform(Far::TopologyRefiner::UniformOptions(c.levels));
    std::vector<V> cur(m.vertex_count()), next;
    std::memcpy(cur.data(), m.positions.data(), m.positions.size() * sizeof(float));
    const Far::PrimvarRefiner primvar(*r);
    for (int k = 1; k <= c.levels; ++k) {
      next.resize(size_t(r->GetLevel(k).GetNumVertices()));
      primvar.Interpolate(k, cur, next);
      cur.swap(next);
    }
    const Far::TopologyLevel& last = r->GetLevel(c.levels);
    std::vector<int> indices;
    indices.reserve(size_t(last.GetNumFaceVertices()));
    for (int f = 0; f < last.GetNumFaces(); ++f) {
      const auto fv = last.GetFaceVertices(f);
      indices.insert(indices.end(), fv.begin(), fv.end());
    }
    faces = size_t(last.GetNumFaces());
    benchmark::DoNotOptimize(cur.data());
    benchmark::DoNotOptimize(indices.data());
  }
  state.counters["faces"] = double(faces);
}

// state.range(1): threads (1, or 0 = all cores); range(2): sigma > 0?
void BM_Fractalize(benchmark::State& state) {
  const Case& c = kCases[state.range(0)];
  const ft::Mesh m = ft::io::read_obj(kMeshes + c.file);
  ft_fractalize_params p = ft::subdiv::default_fractalize_params();
  p.scheme = c.scheme;
  p.levels = c.levels;
  p.threads = int(state.range(1));
  p.sigma = state.range(2) ? 0.1 : 0.0;
  size_t faces = 0;
  for (auto _ : state) {
    const ft::Mesh out = ft::subdiv::fractalize(m, p);
    faces = out.face_count();
    benchmark::DoNotOptimize(out.positions.data());
  }
  state.counters["faces"] = double(faces);
}

BENCHMARK(BM_PlainOpenSubdiv)->ArgName("case")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_Fractalize)
    ->ArgNames({"case", "threads", "displace"})
    ->Args({0, 1, 1})->Args({0, 0, 1})->Args({0, 1, 0})
    ->Args({1, 1, 1})->Args({1, 0, 1})->Args({1, 1, 0})
    ->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
