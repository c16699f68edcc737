#include "planet/cube_sphere.hpp"

#include <cmath>
#include <string>
#include <vector>

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

std::vector<float> heights_in_rows(const Planet& planet, const Directions& u) {
  // Rows of 4096 vertices through the parallel row filler (its progress and cancel).
  const int64_t nv = u.size();
  const int32_t row = 4096, rows = int32_t((nv + row - 1) / row);
  std::vector<float> padded(size_t(rows) * row);
  fill_rows(row, rows, planet.config().threads, planet.config().progress,
            [&](int32_t r, float* out) {
              const int64_t b = int64_t(r) * row, m = std::min<int64_t>(row, nv - b);
              planet.heights(m, u.x.data() + b, u.y.data() + b, u.z.data() + b, out);
            },
            padded.data());
  padded.resize(size_t(nv));
  return padded;
}

void place_on_sphere(const Directions& u, const std::vector<float>& h, double radius, double vertical_scale,
                     Mesh* mesh) {
  const int64_t nv = u.size();
  mesh->positions.resize(size_t(3 * nv));
  for (int64_t v = 0; v < nv; ++v) {
    const double r = radius + vertical_scale * double(h[size_t(v)]);
    mesh->positions[size_t(3 * v)] = float(u.x[size_t(v)] * r);
    mesh->positions[size_t(3 * v + 1)] = float(u.y[size_t(v)] * r);
    mesh->positions[size_t(3 * v + 2)] = float(u.z[size_t(v)] * r);
  }
}

int64_t mesh_vertex_count(int level) { return 6 * (int64_t(1) << (2 * level)) + 2; }
int64_t mesh_face_count(int level) { return 6 * (int64_t(1) << (2 * level)); }

Mesh cube_sphere_mesh(const Planet& planet, int level, double vertical_scale, std::vector<float>* heights) {
  check_int_range("level", level, 0, kMaxMeshLevel);
  check_vertical_scale(vertical_scale);
  const int64_t n = int64_t(1) << level, nv = mesh_vertex_count(level), nf = mesh_face_count(level);
  // positions, unit vectors (3 doubles), heights, indices and the sample
  // map; a midpoint planet's faces and their work too.
  FaceRects whole;
  for (FaceRect& r : whole) r = {0, 0, n, n};
  const uint64_t faces = planet.midpoint() ? checked_bytes(6 * uint64_t(n + 1), uint64_t(n + 1), 4) +
                                                 midpoint_work_bytes(level, whole)
                                           : 0;
  check_allocation(checked_bytes(uint64_t(nv), 12 + 24 + 4) + checked_bytes(uint64_t(nf), 4 * 4 + 4) +
                       checked_bytes(6 * uint64_t(n + 1), uint64_t(n + 1), 4) + faces,
                   "a cube-sphere mesh of level " + std::to_string(level));
  // Vertex ids: every face's samples in order, a sample that an earlier face
  // already has taking that face's id (found from its integer cube point).
  const int64_t side = n + 1;
  std::vector<int32_t> id(size_t(6 * side * side), -1);
  Directions u{size_t(nv)};
  std::vector<int64_t> first_sample(static_cast<size_t>(nv));  // each vertex's first (face, j, i), as an index of id
  int64_t count = 0;
  for (int f = 0; f < 6; ++f) {
    for (int64_t j = 0; j < side; ++j) {
      for (int64_t i = 0; i < side; ++i) {
        const CubePoint p = cube_point(f, i, j, n);
        int32_t v = -1;
        const bool edge = i == 0 || j == 0 || i == n || j == n;
        for (int g = 0; edge && g < f && v < 0; ++g) {
          int64_t gi, gj;
          if (face_sample(p, g, n, &gi, &gj)) v = id[size_t((g * side + gj) * side + gi)];
        }
        if (v < 0) {
          if (count == nv) fail(FT_ERR_INTERNAL, "cube-sphere mesh: more than " + std::to_string(nv) + " vertices");
          v = int32_t(count++);
          u.set(size_t(v), unit_vector(p));
          first_sample[size_t(v)] = (f * side + j) * side + i;
        }
        id[size_t((f * side + j) * side + i)] = v;
      }
    }
  }
  if (count != nv) fail(FT_ERR_INTERNAL, "cube-sphere mesh: vertex count " + std::to_string(count));
  // A midpoint planet's heights are its faces' samples.
  std::vector<float> padded(static_cast<size_t>(nv));
  if (planet.midpoint()) {
    std::vector<float> all(size_t(6 * side * side));
    std::array<float*, 6> out;
    for (int f = 0; f < 6; ++f) out[size_t(f)] = all.data() + f * side * side;
    midpoint_faces(planet.midpoint_config(), level, whole, out, planet.config().threads, planet.config().progress);
    planet.raise_to_sea(int64_t(all.size()), all.data());
    for (int64_t v = 0; v < nv; ++v) padded[size_t(v)] = all[size_t(first_sample[size_t(v)])];
  } else {
    padded = heights_in_rows(planet, u);
  }
  padded.resize(size_t(nv));
  Mesh mesh;
  place_on_sphere(u, padded, planet.config().radius, vertical_scale, &mesh);
  mesh.face_sizes.assign(size_t(nf), 4);
  mesh.face_indices.reserve(size_t(4 * nf));
  for (int f = 0; f < 6; ++f) {
    // (i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1) turns about s x t; keep
    // it when that points outwards, else walk the quad the other way.
    const FaceAxes& a = kFaces[f];
    const int cross[3] = {a.s[1] * a.t[2] - a.s[2] * a.t[1], a.s[2] * a.t[0] - a.s[0] * a.t[2],
                          a.s[0] * a.t[1] - a.s[1] * a.t[0]};
    const bool outward = cross[0] * a.n[0] + cross[1] * a.n[1] + cross[2] * a.n[2] > 0;
    auto at = [&](int64_t i, int64_t j) { return id[size_t((f * side + j) * side + i)]; };
    for (int64_t j = 0; j < n; ++j) {
      for (int64_t i = 0; i < n; ++i) {
        const int32_t q[4] = {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)};
        if (outward)
          mesh.face_indices.insert(mesh.face_indices.end(), {q[0], q[1], q[2], q[3]});
        else
          mesh.face_indices.insert(mesh.face_indices.end(), {q[0], q[3], q[2], q[1]});
      }
    }
  }
  if (heights) *heights = std::move(padded);
  return mesh;
}

}  // namespace ft::planet
