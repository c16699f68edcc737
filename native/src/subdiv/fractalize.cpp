// SPDX-License-Identifier: GPL-3.0-or-later
// Fractalization on OpenSubdiv, level by level:
//
//   1. Far::TopologyRefiner refines the base topology uniformly to L levels.
//   2. For k = 1..L, Far::PrimvarRefiner interpolates the (already displaced)
//      positions of level k-1 to level k, then the level's vertex normals are
//      computed, and the vertices new at level k (Voss) or all vertices
//      (additions) move along the normal by sigma 2^(-kH) s g.
//
// Vertex identity for the random numbers: (seed, level k, vertex index at
// level k) -> Counter{0, k, Stream::kSubdiv}, index = vertex index. OpenSubdiv
// numbers refined vertices deterministically from the base topology (children
// of vertices first, then of faces, then of edges, each in parent order), so
// the same mesh and seed give the same numbers on any machine and thread
// count, and a run with L - 1 levels is exactly the level L - 1 stage of a
// run with L levels (the tests use this to measure the displacement added at
// each level). The key changes when the base topology changes; that is the
// price of a key without hashing parent chains.
#include "subdiv/fractalize.hpp"
#include "subdiv/fractalize_params.hpp"

#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/memory.hpp"
#include "core/parallel.hpp"
#include "core/progress.hpp"
#include "core/rng.hpp"
#include "subdiv/mesh_validation.hpp"

namespace ft::subdiv {

using namespace OpenSubdiv;

namespace detail {

// A primvar of N floats: xyz, plus (N = 4) the displacement scale factor.
template <int N>
struct Primvar {
  float v[N];
  void Clear(void* = nullptr) {
    for (float& x : v) x = 0.0f;
  }
  void AddWithWeight(const Primvar& src, float w) {
    for (int i = 0; i < N; ++i) v[i] += w * src.v[i];
  }
};

std::unique_ptr<Far::TopologyRefiner> make_refiner(const Mesh& m, int scheme) {
  const Sdc::SchemeType type = scheme == FT_SCHEME_LOOP       ? Sdc::SCHEME_LOOP
                               : scheme == FT_SCHEME_BILINEAR ? Sdc::SCHEME_BILINEAR
                                                              : Sdc::SCHEME_CATMARK;
  Sdc::Options options;
  // Boundaries follow the smooth boundary curve and corners stay put, so an
  // open terrain patch keeps its outline.
  options.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER);
  Far::TopologyDescriptor d;
  d.numVertices = int(m.vertex_count());
  d.numFaces = int(m.face_count());
  d.numVertsPerFace = m.face_sizes.data();
  d.vertIndicesPerFace = m.face_indices.data();
  d.numCreases = int(m.crease_sharpness.size());
  d.creaseVertexIndexPairs = m.crease_pairs.data();
  d.creaseWeights = m.crease_sharpness.data();
  d.numCorners = int(m.corner_sharpness.size());
  d.cornerVertexIndices = m.corner_vertices.data();
  d.cornerWeights = m.corner_sharpness.data();
  using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  // OpenSubdiv reports problems through process-wide callbacks, which we
  // leave alone: in Blender the library is shared with Blender's own
  // OpenSubdiv. validate_mesh() catches what OpenSubdiv would refuse first.
  std::unique_ptr<Far::TopologyRefiner> r(Factory::Create(d, Factory::Options(type, options)));
  if (!r) invalid("OpenSubdiv cannot refine this mesh (its message went to the standard output)");
  return r;
}

// Bytes a fractalization to `levels` needs at its peak, estimated from the
// face corners of the last level: OpenSubdiv's topology of all levels, two
// primvar buffers, normals and the output mesh. Measured peak: 52 bytes per
// last-level corner (cube, 9 levels, 6.3M corners, 326 MB); we assume 72.
uint64_t estimate_bytes(const Mesh& m, int scheme, int levels, uint64_t* last_corners) {
  uint64_t corners = 0;  // face corners at level 1
  for (int32_t n : m.face_sizes) corners += scheme == FT_SCHEME_LOOP ? 12 : 4 * uint64_t(n);
  for (int k = 1; k < levels; ++k) corners = corners > (UINT64_MAX >> 3) ? UINT64_MAX : corners * 4;
  *last_corners = corners;
  return checked_bytes(corners, 72);
}

template <int N>
class Fractalizer {
 public:
  Fractalizer(const Mesh& m, const ft_fractalize_params& p, const Far::TopologyRefiner& r)
      : m_(m), p_(p), r_(r), threads_(resolve_threads(p.threads)) {}

  Mesh run() {
    const Progress progress(p_.progress, p_.progress_user);
    std::vector<Primvar<N>> cur(m_.vertex_count()), next;
    for (size_t i = 0; i < cur.size(); ++i)
      for (int c = 0; c < 3; ++c) cur[i].v[c] = m_.positions[3 * i + c];
    if constexpr (N == 4) {
      const std::vector<float> s = base_scales();
      for (size_t i = 0; i < cur.size(); ++i) cur[i].v[3] = s[i];
    }
    const Far::PrimvarRefiner primvar(r_);
    progress.report(0.0);
    for (int k = 1; k <= p_.levels; ++k) {
      next.resize(size_t(r_.GetLevel(k).GetNumVertices()));
      primvar.Interpolate(k, cur, next);
      if (p_.sigma > 0) displace(k, next);
      cur.swap(next);
      progress.report(double(k) / p_.levels);
    }
    return output(cur);
  }

 private:
  // Per base vertex: the weight (1 without weights) times, optionally, the
  // mean length of the base edges at the vertex.
  std::vector<float> base_scales() const {
    std::vector<float> s(m_.vertex_count(), 1.0f);
    if (p_.weights) s.assign(p_.weights, p_.weights + s.size());
    if (!p_.scale_by_edge_length) return s;
    const Far::TopologyLevel& base = r_.GetLevel(0);
    std::vector<double> sum(s.size(), 0.0);
    std::vector<int> count(s.size(), 0);
    for (int e = 0; e < base.GetNumEdges(); ++e) {
      const auto ev = base.GetEdgeVertices(e);
      const auto a = m_.vertex(size_t(ev[0])), b = m_.vertex(size_t(ev[1]));
      double len2 = 0;
      for (int c = 0; c < 3; ++c) len2 += (double(a[c]) - b[c]) * (double(a[c]) - b[c]);
      for (int j = 0; j < 2; ++j) sum[size_t(ev[j])] += std::sqrt(len2), ++count[size_t(ev[j])];
    }
    for (size_t v = 0; v < s.size(); ++v) s[v] *= count[v] ? float(sum[v] / count[v]) : 0.0f;
    return s;
  }

  void displace(int k, std::vector<Primvar<N>>& x) {
    const Far::TopologyLevel& level = r_.GetLevel(k);
    const Far::TopologyLevel& parent = r_.GetLevel(k - 1);
    const int nf = level.GetNumFaces(), nv = level.GetNumVertices();

    // Vertex normals: each face's Newell vector (its vector area, so larger
    // faces weigh more) scattered to its corners, serially in face order so
    // the sums do not depend on threads. A parallel gather would need the
    // vertex-face relations, which OpenSubdiv only builds for the last level
    // at a higher cost than this loop (fullTopologyInLastLevel).
    normal_.assign(3 * size_t(nv), 0.0f);
    float* nrm = normal_.data();
    for (int f = 0; f < nf; ++f) {
      const auto fv = level.GetFaceVertices(f);
      float nx = 0, ny = 0, nz = 0;
      for (int i = 0, n = fv.size(); i < n; ++i) {
        const float* a = x[size_t(fv[i])].v;
        const float* b = x[size_t(fv[i + 1 < n ? i + 1 : 0])].v;
        nx += (a[1] - b[1]) * (a[2] + b[2]);
        ny += (a[2] - b[2]) * (a[0] + b[0]);
        nz += (a[0] - b[0]) * (a[1] + b[1]);
      }
      for (int v : fv) {
        float* o = nrm + 3 * size_t(v);
        o[0] += nx, o[1] += ny, o[2] += nz;
      }
    }

    // Vertices that stay: children of vertices (Voss moves only the new
    // ones), and with fix_boundary the children of boundary vertices and
    // edges of the parent level (a face's child is never on a boundary).
    skip_.assign(size_t(nv), 0);
    for (int v = 0; v < parent.GetNumVertices(); ++v)
      if (p_.mode == FT_FRACTALIZE_MIDPOINT || (p_.fix_boundary && parent.IsVertexBoundary(v)))
        skip_[size_t(parent.GetVertexChildVertex(v))] = 1;
    if (p_.fix_boundary)
      for (int e = 0; e < parent.GetNumEdges(); ++e)
        if (parent.IsEdgeBoundary(e)) skip_[size_t(parent.GetEdgeChildVertex(e))] = 1;

    const float amp = float(p_.sigma * std::pow(2.0, -k * p_.hurst));
    const Counter counter{0, uint32_t(k), Stream::kSubdiv};
    const uint8_t* skip = skip_.data();
    // Chunks of a fixed size, so the random numbers are drawn in batches
    // whose addresses do not depend on the thread count.
    constexpr int kChunk = 4096;
    const int chunks = (nv + kChunk - 1) / kChunk;
#pragma omp parallel num_threads(threads_) if (chunks > 1)  // no thread start-up for small levels
    {
      std::vector<float> g(kChunk);
#pragma omp for schedule(static)
      for (int c = 0; c < chunks; ++c) {
        const int v0 = c * kChunk, v1 = std::min(nv, v0 + kChunk);
        gaussian_fill(p_.seed, counter, uint64_t(v0), size_t(v1 - v0), g.data());
        for (int v = v0; v < v1; ++v) {
          if (skip[v]) continue;
          const float* n = nrm + 3 * size_t(v);
          const float len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
          if (!(len > 0)) continue;  // no faces or a fan that cancels: no direction
          float d = amp * g[size_t(v - v0)] / len;
          if constexpr (N == 4) d *= x[size_t(v)].v[3];
          float* q = x[size_t(v)].v;
          q[0] += d * n[0], q[1] += d * n[1], q[2] += d * n[2];
        }
      }
    }
  }

  Mesh output(const std::vector<Primvar<N>>& x) const {
    const Far::TopologyLevel& last = r_.GetLevel(p_.levels);
    Mesh out;
    out.positions.resize(3 * x.size());
    if constexpr (N == 3) {
      static_assert(sizeof(Primvar<3>) == 3 * sizeof(float));
      std::memcpy(out.positions.data(), x.data(), out.positions.size() * sizeof(float));
    } else {
      for (size_t i = 0; i < x.size(); ++i)
        for (int c = 0; c < 3; ++c) out.positions[3 * i + c] = x[i].v[c];
    }
    const int nf = last.GetNumFaces();
    const int size = p_.scheme == FT_SCHEME_LOOP ? 3 : 4;
    out.face_sizes.assign(size_t(nf), size);
    out.face_indices.resize(size_t(nf) * size);
    for (int f = 0; f < nf; ++f) {
      const auto fv = last.GetFaceVertices(f);
      std::copy(fv.begin(), fv.end(), out.face_indices.begin() + size_t(f) * size);
    }
    return out;
  }

  const Mesh& m_;
  const ft_fractalize_params& p_;
  const Far::TopologyRefiner& r_;
  const int threads_;
  std::vector<float> normal_;
  std::vector<uint8_t> skip_;
};

}  // namespace detail

Mesh fractalize(const Mesh& mesh, const ft_fractalize_params& p) {
  check_struct_size(p.struct_size, sizeof(ft_fractalize_params), "ft_fractalize_params");
  check_ranges(fractalize_param_table(), &p);  // each field's range; the mesh and the weights follow
  validate_mesh(mesh);
  if (p.scheme == FT_SCHEME_LOOP) validate_triangles(mesh);
  if (p.weights)
    for (size_t i = 0; i < mesh.vertex_count(); ++i)
      if (!std::isfinite(p.weights[i]))
        invalid("weights[" + std::to_string(i) + "] is " + format_number(p.weights[i]) + "; weights must be finite");

  uint64_t corners = 0;
  check_allocation(detail::estimate_bytes(mesh, p.scheme, p.levels, &corners), "fractalizing to " +
                   std::to_string(p.levels) + " levels");
  if (corners > uint64_t(INT32_MAX))
    fail(FT_ERR_TOO_LARGE, std::to_string(p.levels) + " levels would make " + std::to_string(corners) +
                               " face corners; OpenSubdiv allows at most 2^31 - 1: use fewer levels");

  auto refiner = detail::make_refiner(mesh, p.scheme);
  refiner->RefineUniform(Far::TopologyRefiner::UniformOptions(p.levels));
  if (p.weights || p.scale_by_edge_length) return detail::Fractalizer<4>(mesh, p, *refiner).run();
  return detail::Fractalizer<3>(mesh, p, *refiner).run();
}

}  // namespace ft::subdiv
