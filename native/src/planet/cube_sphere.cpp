// SPDX-License-Identifier: GPL-3.0-or-later
#include "planet/cube_sphere.hpp"

#include <algorithm>
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/buffer.hpp"
#include "core/error.hpp"
#include "core/memory.hpp"
#include "planet/midpoint_sphere.hpp"

namespace ft::planet {
namespace {

// Normal n, column direction s and row direction t of each face (planet.h's table).
struct FaceAxes {
  int n[3], s[3], t[3];
};
constexpr FaceAxes kFaces[6] = {
    {{1, 0, 0}, {0, 0, -1}, {0, -1, 0}},   // +X: ( 1, -t, -s)
    {{-1, 0, 0}, {0, 0, 1}, {0, -1, 0}},   // -X: (-1, -t,  s)
    {{0, 1, 0}, {1, 0, 0}, {0, 0, 1}},     // +Y: ( s,  1,  t)
    {{0, -1, 0}, {1, 0, 0}, {0, 0, -1}},   // -Y: ( s, -1, -t)
    {{0, 0, 1}, {1, 0, 0}, {0, -1, 0}},    // +Z: ( s, -t,  1)
    {{0, 0, -1}, {-1, 0, 0}, {0, -1, 0}},  // -Z: (-s, -t, -1)
};

int64_t dot(const int* a, const CubePoint& p) { return a[0] * p.x + a[1] * p.y + a[2] * p.z; }

// The closed mesh's progress bar: its vertices, their heights, the
// positions, then the quads, each part about as long as it takes: a level-11
// fBm planet of the default settings on one thread took 0.49, 3.33, 0.23 and
// 0.05 s (the fastest of 5 runs at load 4).
constexpr double kVertexShare = 0.12, kHeightShare = 0.8, kPlaceShare = 0.06;
// Rows are handed out (and reported) in tasks of about this many samples:
// a report is a call into Python in Blender, microseconds, and a row of a
// level-11 face 50 microseconds' work.
constexpr int64_t kTaskSamples = 1 << 16;

// for_rows over `count` rows of `width` samples each, in tasks of a few rows.
void for_row_tasks(int64_t count, int64_t width, int threads, const Progress& progress,
                   const std::function<void(int64_t)>& row) {
  const int64_t per = std::max<int64_t>(1, kTaskSamples / std::max<int64_t>(width, 1));
  for_rows((count + per - 1) / per, threads, progress, [&](int64_t t) {
    for (int64_t r = t * per; r < std::min(count, (t + 1) * per); ++r) row(r);
  });
}

}  // namespace

std::array<int, 3> face_normal(int face) {
  const FaceAxes& f = kFaces[face];
  return {f.n[0], f.n[1], f.n[2]};
}

CubePoint face_point(int face, int64_t d, int64_t s, int64_t t) {
  const FaceAxes& f = kFaces[face];
  return {d * f.n[0] + s * f.s[0] + t * f.t[0], d * f.n[1] + s * f.s[1] + t * f.t[1],
          d * f.n[2] + s * f.s[2] + t * f.t[2]};
}

CubePoint cube_point(int face, int64_t i, int64_t j, int64_t n) { return face_point(face, n, 2 * i - n, 2 * j - n); }

CubePoint folded_point(int face, int64_t i, int64_t j, int64_t n) {
  // Past an edge the plane turns by 90 degrees into the cube: what lies
  // beyond it comes off the normal coordinate instead.
  int64_t d = n, s = 2 * i - n, t = 2 * j - n;
  if (s < -n) d -= -n - s, s = -n;
  else if (s > n) d -= s - n, s = n;
  else if (t < -n) d -= -n - t, t = -n;
  else if (t > n) d -= t - n, t = n;
  return face_point(face, d, s, t);
}

int locate(const CubePoint& p, int64_t n, int64_t* i, int64_t* j) {
  for (int g = 0; g < 6; ++g)
    if (face_sample(p, g, n, i, j)) return g;
  fail(FT_ERR_INTERNAL, "cube point (" + std::to_string(p.x) + ", " + std::to_string(p.y) + ", " +
                            std::to_string(p.z) + ") is on no face at N = " + std::to_string(n));
}

int face_of_direction(double x, double y, double z, double* s, double* t) {
  const double ax = std::fabs(x), ay = std::fabs(y), az = std::fabs(z);
  const int face = ax >= ay && ax >= az ? (x >= 0 ? 0 : 1) : ay >= az ? (y >= 0 ? 2 : 3) : (z >= 0 ? 4 : 5);
  const FaceAxes& f = kFaces[face];
  const double p[3] = {x, y, z};
  const double d = f.n[0] * p[0] + f.n[1] * p[1] + f.n[2] * p[2];
  *s = (f.s[0] * p[0] + f.s[1] * p[1] + f.s[2] * p[2]) / d;
  *t = (f.t[0] * p[0] + f.t[1] * p[1] + f.t[2] * p[2]) / d;
  return face;
}

std::array<double, 3> unit_vector(const CubePoint& p) {
  // Exact: |x|, |y|, |z| <= 2^26, so the sum of squares is an integer below 2^53.
  const double x = double(p.x), y = double(p.y), z = double(p.z);
  const double len = std::sqrt(x * x + y * y + z * z);
  return {x / len, y / len, z / len};
}

bool face_sample(const CubePoint& p, int face, int64_t n, int64_t* i, int64_t* j) {
  const FaceAxes& f = kFaces[face];
  if (dot(f.n, p) != n) return false;
  const int64_t s = dot(f.s, p), t = dot(f.t, p);
  if (((s + n) & 1) || ((t + n) & 1)) return false;
  *i = (s + n) / 2;
  *j = (t + n) / 2;
  return *i >= 0 && *i <= n && *j >= 0 && *j <= n;
}

void validate_patch(int level, int face, int64_t x0, int64_t y0, int64_t w, int64_t h) {
  check_int_range("level", level, 0, kMaxLevel);
  check_int_range("face", face, 0, 5);
  const int64_t side = (int64_t(1) << level) + 1;
  if (w < 1 || h < 1 || w > 65536 || h > 65536)
    invalid("a patch's width and height must be in 1..65536, got " + std::to_string(w) + " x " + std::to_string(h));
  if (x0 < 0 || y0 < 0 || x0 + w > side || y0 + h > side)
    invalid("the patch (" + std::to_string(x0) + ", " + std::to_string(y0) + ") + " + std::to_string(w) + " x " +
            std::to_string(h) + " lies outside face " + std::to_string(face) + ", whose samples at level " +
            std::to_string(level) + " are 0.." + std::to_string(side - 1) + " along each side");
}

Heightfield face_patch(const Planet& planet, int level, int face, int64_t x0, int64_t y0, int32_t w, int32_t h) {
  validate_patch(level, face, x0, y0, w, h);
  const int64_t n = int64_t(1) << level;
  if (planet.midpoint()) {
    FaceRects rects;
    rects[size_t(face)] = {x0, y0, x0 + w - 1, y0 + h - 1};
    check_allocation(checked_bytes(uint64_t(w), uint64_t(h), sizeof(float)) + midpoint_work_bytes(level, rects),
                     "a midpoint planet's patch of " + std::to_string(w) + " x " + std::to_string(h));
  }
  Heightfield hf(w, h);
  hf.set_world_size(double(w - 1) * 2.0 * planet.config().radius / double(n));
  if (planet.midpoint()) {
    FaceRects rects;
    rects[size_t(face)] = {x0, y0, x0 + w - 1, y0 + h - 1};
    std::array<float*, 6> out{};
    out[size_t(face)] = hf.data();
    midpoint_faces(planet.midpoint_config(), level, rects, out, planet.config().threads, planet.config().progress);
    planet.raise_to_sea(int64_t(w) * h, hf.data());
    return hf;
  }
  fill_rows(w, h, planet.config().threads, planet.config().progress,
            [&](int32_t y, float* row) {
              Directions d{size_t(w)};
              for (int32_t x = 0; x < w; ++x) d.set(size_t(x), unit_vector(cube_point(face, x0 + x, y0 + y, n)));
              planet.heights(d, row);
            },
            hf.data());
  return hf;
}

void check_vertical_scale(double vertical_scale) {
  if (!std::isfinite(vertical_scale) || std::fabs(vertical_scale) > 1e6)
    invalid("vertical_scale must be finite and within +-1e6, got " + format_number(vertical_scale));
}

std::vector<float> heights_in_rows(const Planet& planet, const Directions& u, const Progress& progress) {
  // Rows of 4096 vertices through the parallel row filler (its progress and cancel).
  const int64_t nv = u.size();
  const int32_t row = 4096, rows = int32_t((nv + row - 1) / row);
  std::vector<float> padded(size_t(rows) * row);
  fill_rows(row, rows, planet.config().threads, progress,
            [&](int32_t r, float* out) {
              const int64_t b = int64_t(r) * row, m = std::min<int64_t>(row, nv - b);
              planet.heights(m, u.x.data() + b, u.y.data() + b, u.z.data() + b, out);
            },
            padded.data());
  padded.resize(size_t(nv));
  return padded;
}

void place_on_sphere(const Directions& u, const std::vector<float>& h, double radius, double vertical_scale,
                     int threads, const Progress& progress, float* xyz) {
  const int64_t nv = u.size();
  for_row_tasks(nv, 1, threads, progress, [&](int64_t v) {
    const double r = radius + vertical_scale * double(h[size_t(v)]);
    xyz[3 * v] = float(u.x[size_t(v)] * r);
    xyz[3 * v + 1] = float(u.y[size_t(v)] * r);
    xyz[3 * v + 2] = float(u.z[size_t(v)] * r);
  });
}

int64_t mesh_vertex_count(int level) { return 6 * (int64_t(1) << (2 * level)) + 2; }
int64_t mesh_face_count(int level) { return 6 * (int64_t(1) << (2 * level)); }

namespace {

// The closed mesh's vertices: each sample's vertex id (samples face by face,
// row by row: id[(f side + j) side + i]), each vertex's direction and (if
// asked) its first sample there. Not zero-filled: every element is written
// once, by the rows that report progress.
struct CubeVertices {
  Buffer<int32_t> id;
  Directions u;
  Buffer<int64_t> first_sample;
};

// Vertex ids: every face's samples in order, a sample that an earlier face
// already has taking that face's id. Numbered in parallel rows: a first pass
// over the edge samples finds the shared ones (and the sample that first
// has each: that of the lowest face holding it, which no earlier face has)
// and so where each row's new ids start; the rows then number their new
// samples from there, and the shared ones copy their first sample's id.
// Each id depends on its position alone: the same numbering on any thread
// count, and as the one serial loop over the samples gave.
CubeVertices number_vertices(int level, bool first_samples, int threads, const Progress& progress) {
  const int64_t n = int64_t(1) << level, side = n + 1, rows = 6 * side, nv = mesh_vertex_count(level);
  struct Shared {
    int64_t sample, first;
  };
  std::vector<Shared> shared;
  std::vector<int64_t> row_first(size_t(rows) + 1, 0);  // each row's first new id
  std::vector<size_t> row_shared(size_t(rows) + 1, 0);  // and its first entry in `shared`
  for (int64_t r = 0; r < rows; ++r) {
    row_shared[size_t(r)] = shared.size();
    const int f = int(r / side);
    // Only a face's edge samples can lie on another face.
    const int64_t j = r % side, step = j == 0 || j == n ? 1 : n;
    int64_t fresh = side;
    for (int64_t i = 0; i < side; i += step) {
      const CubePoint p = cube_point(f, i, j, n);
      int64_t gi, gj;
      for (int g = 0; g < f; ++g) {
        if (!face_sample(p, g, n, &gi, &gj)) continue;
        shared.push_back({r * side + i, (g * side + gj) * side + gi});
        --fresh;
        break;
      }
    }
    row_first[size_t(r) + 1] = row_first[size_t(r)] + fresh;
  }
  row_shared[size_t(rows)] = shared.size();
  if (row_first.back() != nv)
    fail(FT_ERR_INTERNAL, "cube-sphere mesh: " + std::to_string(row_first.back()) + " vertices, not " +
                              std::to_string(nv));
  CubeVertices out{Buffer<int32_t>(size_t(rows * side)), Directions{size_t(nv)},
                   first_samples ? Buffer<int64_t>(size_t(nv)) : Buffer<int64_t>()};
  for_row_tasks(rows, side, threads, progress, [&](int64_t r) {
    const int f = int(r / side);
    const int64_t j = r % side;
    int64_t v = row_first[size_t(r)];
    size_t s = row_shared[size_t(r)];
    for (int64_t i = 0; i < side; ++i) {
      const int64_t sample = r * side + i;
      if (s < row_shared[size_t(r) + 1] && shared[s].sample == sample) {
        ++s;  // numbered by its first face, below
        continue;
      }
      out.id[size_t(sample)] = int32_t(v);
      out.u.set(size_t(v), unit_vector(cube_point(f, i, j, n)));
      if (first_samples) out.first_sample[size_t(v)] = sample;
      ++v;
    }
  });
  for (const Shared& s : shared) out.id[size_t(s.sample)] = out.id[size_t(s.first)];
  return out;
}

// The quads of the closed mesh (4 corners each) from its samples' vertex ids,
// quad row (f, j) of n at its own place in `corners`.
void write_quads(const Buffer<int32_t>& id, int64_t n, int threads, const Progress& progress, int32_t* corners) {
  const int64_t side = n + 1;
  for_row_tasks(6 * n, n, threads, progress, [&](int64_t r) {
    const int f = int(r / n);
    const int64_t j = r % n;
    // (i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1) turns about s x t; keep
    // it when that points outwards, else walk the quad the other way.
    const FaceAxes& a = kFaces[f];
    const int cross[3] = {a.s[1] * a.t[2] - a.s[2] * a.t[1], a.s[2] * a.t[0] - a.s[0] * a.t[2],
                          a.s[0] * a.t[1] - a.s[1] * a.t[0]};
    const bool outward = cross[0] * a.n[0] + cross[1] * a.n[1] + cross[2] * a.n[2] > 0;
    const int32_t* row = id.data() + (f * side + j) * side;  // this row's ids, then the next's
    int32_t* q = corners + 4 * r * n;
    for (int64_t i = 0; i < n; ++i, q += 4) {
      const int32_t c[4] = {row[i], row[i + 1], row[side + i + 1], row[side + i]};
      if (outward)
        q[0] = c[0], q[1] = c[1], q[2] = c[2], q[3] = c[3];
      else
        q[0] = c[0], q[1] = c[3], q[2] = c[2], q[3] = c[1];
    }
  });
}

// Every sample of every face at N = n.
FaceRects whole_faces(int64_t n) {
  FaceRects whole;
  for (FaceRect& r : whole) r = {0, 0, n, n};
  return whole;
}

// Bytes of the vertices' ids, directions and heights (a midpoint planet's
// faces, first samples and their work too), besides the output arrays.
uint64_t mesh_work_bytes(const Planet& planet, int level) {
  const int64_t n = int64_t(1) << level, nv = mesh_vertex_count(level);
  const uint64_t samples = checked_bytes(6 * uint64_t(n + 1), uint64_t(n + 1), 4);
  uint64_t bytes = samples + checked_bytes(uint64_t(nv), 24 + 4);
  if (planet.midpoint())
    bytes += samples + checked_bytes(uint64_t(nv), 8) + midpoint_work_bytes(level, whole_faces(n));
  return bytes;
}

}  // namespace

void cube_sphere_arrays(const Planet& planet, int level, double vertical_scale, const MeshArrays& out,
                        uint64_t output_bytes) {
  check_int_range("level", level, 0, kMaxMeshLevel);
  check_vertical_scale(vertical_scale);
  check_allocation(mesh_work_bytes(planet, level) + output_bytes,
                   "a cube-sphere mesh of level " + std::to_string(level));
  const int64_t n = int64_t(1) << level, side = n + 1, nv = mesh_vertex_count(level);
  const Progress& progress = planet.config().progress;
  const int threads = planet.config().threads;
  // Each part reports after every task of rows, so a cancel waits for one at most.
  const double placed = kVertexShare + kHeightShare + kPlaceShare;
  const ProgressPart vertex_part(progress, 0.0, kVertexShare), height_part(progress, kVertexShare, kHeightShare),
      place_part(progress, kVertexShare + kHeightShare, kPlaceShare), quad_part(progress, placed, 1.0 - placed);
  CubeVertices cube = number_vertices(level, planet.midpoint(), threads, vertex_part.progress());
  std::vector<float> h;
  if (planet.midpoint()) {
    // A midpoint planet's heights are its faces' samples.
    std::vector<float> all(size_t(6 * side * side));
    std::array<float*, 6> faces;
    for (int f = 0; f < 6; ++f) faces[size_t(f)] = all.data() + f * side * side;
    midpoint_faces(planet.midpoint_config(), level, whole_faces(n), faces, threads, height_part.progress());
    planet.raise_to_sea(int64_t(all.size()), all.data());
    h.resize(size_t(nv));
    for (int64_t v = 0; v < nv; ++v) h[size_t(v)] = all[size_t(cube.first_sample[size_t(v)])];
  } else {
    h = heights_in_rows(planet, cube.u, height_part.progress());
  }
  if (out.xyz)
    place_on_sphere(cube.u, h, planet.config().radius, vertical_scale, threads, place_part.progress(), out.xyz);
  if (out.heights) std::copy(h.begin(), h.end(), out.heights);
  if (out.corners) write_quads(cube.id, n, threads, quad_part.progress(), out.corners);
  progress.report(1.0);
}

Mesh cube_sphere_mesh(const Planet& planet, int level, double vertical_scale, std::vector<float>* heights) {
  check_int_range("level", level, 0, kMaxMeshLevel);
  const uint64_t nv = uint64_t(mesh_vertex_count(level)), nf = uint64_t(mesh_face_count(level));
  // Positions, quads and their sizes, and the heights.
  const uint64_t output_bytes = checked_bytes(nv, 12 + 4) + checked_bytes(nf, 4 * 4 + 4);
  check_allocation(mesh_work_bytes(planet, level) + output_bytes,
                   "a cube-sphere mesh of level " + std::to_string(level));
  Mesh mesh;
  mesh.positions.resize(size_t(3 * nv));
  mesh.face_indices.resize(size_t(4 * nf));
  mesh.face_sizes.assign(size_t(nf), 4);
  std::vector<float> h(heights ? size_t(nv) : 0);
  cube_sphere_arrays(planet, level, vertical_scale,
                     {mesh.positions.data(), mesh.face_indices.data(), heights ? h.data() : nullptr}, output_bytes);
  if (heights) *heights = std::move(h);
  return mesh;
}

}  // namespace ft::planet
