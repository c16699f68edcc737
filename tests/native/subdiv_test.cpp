// SPDX-License-Identifier: GPL-3.0-or-later
// The subdiv layer: fractalization on OpenSubdiv, mesh validation, OBJ and
// POV-Ray mesh2 output. Plain subdivision (zero displacement) is checked
// against the schemes' limit surfaces, and displacements are measured from
// the schemes' own rules, both computed here without OpenSubdiv.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/memory.hpp"
#include "io/atomic_file.hpp"
#include "io/obj_io.hpp"
#include "povray/mesh2_export.hpp"
#include "subdiv/fractalize.hpp"
#include "subdiv/mesh_validation.hpp"

namespace ft {
namespace {

namespace fs = std::filesystem;

// The shipped example meshes (compilers get absolute source paths from CMake).
const std::string kMeshes = (fs::path(__FILE__).parent_path() / "../../examples/meshes/").lexically_normal().string();

Mesh cube() { return io::read_obj(kMeshes + "cube.obj"); }
Mesh icosahedron() { return io::read_obj(kMeshes + "icosahedron.obj"); }
Mesh mountain() { return io::read_obj(kMeshes + "mountain.obj"); }

ft_fractalize_params params(int levels, double sigma, int scheme = FT_SCHEME_CATMARK) {
  ft_fractalize_params p = subdiv::default_fractalize_params();
  p.levels = levels;
  p.sigma = sigma;
  p.scheme = scheme;
  p.seed = 11;
  return p;
}

// Plain (zero-displacement) subdivision of a closed mesh without creases by
// one level, by the schemes' published rules rather than OpenSubdiv: `coarse`
// and `fine` are consecutive levels of one fractalization. Levels number the
// children of the old vertices first, in their order, so entry v <
// coarse.vertex_count() is old vertex v's child: Loop's (1 - n beta) v + beta
// sum of its n neighbours, beta = (5/8 - (3/8 + cos(2 pi / n) / 4)^2) / n;
// Catmull-Clark's (Q + 2 R + (n - 3) v) / n, Q the mean of its faces'
// centroids, R of its edges' midpoints. For Loop the edge children follow: a
// new vertex joins the two old ends of the edge it splits (found in `fine`),
// 3/8 (a + b) + 1/8 (c + d) with c, d the coarse vertices opposite the edge.
// (Catmull-Clark's new vertices are left NaN: the tests compare old ones.)
std::vector<double> plain_refinement(const Mesh& coarse, const Mesh& fine, int scheme) {
  const size_t old_count = coarse.vertex_count();
  std::vector<std::set<int32_t>> ring(old_count);
  std::vector<std::vector<std::array<double, 3>>> centroids(old_count);
  std::map<std::pair<int32_t, int32_t>, std::vector<int32_t>> opposite;  // coarse edge (a < b) -> third vertices
  size_t first = 0;
  for (int32_t n : coarse.face_sizes) {
    const int32_t* f = &coarse.face_indices[first];
    std::array<double, 3> c{};
    for (int32_t i = 0; i < n; ++i)
      for (int k = 0; k < 3; ++k) c[size_t(k)] += coarse.positions[size_t(3 * f[i] + k)] / n;
    for (int32_t i = 0; i < n; ++i) {
      const int32_t a = f[i], b = f[(i + 1) % n];
      ring[size_t(a)].insert(b), ring[size_t(b)].insert(a);
      centroids[size_t(a)].push_back(c);
      if (n == 3) opposite[{std::min(a, b), std::max(a, b)}].push_back(f[(i + 2) % n]);
    }
    first += size_t(n);
  }
  auto at = [&](int32_t v, int k) { return double(coarse.positions[size_t(3 * v + k)]); };
  std::vector<double> out(3 * fine.vertex_count(), NAN);
  for (size_t v = 0; v < old_count; ++v) {
    const double n = double(ring[v].size());
    for (int k = 0; k < 3; ++k) {
      double sum = 0;
      for (int32_t u : ring[v]) sum += at(u, k);
      if (scheme == FT_SCHEME_LOOP) {
        const double beta = (0.625 - std::pow(0.375 + 0.25 * std::cos(2 * M_PI / n), 2)) / n;
        out[3 * v + size_t(k)] = (1 - n * beta) * at(int32_t(v), k) + beta * sum;
      } else {
        double q = 0;
        for (const auto& c : centroids[v]) q += c[size_t(k)] / double(centroids[v].size());
        const double r = (at(int32_t(v), k) + sum / n) / 2;  // mean of the edge midpoints
        out[3 * v + size_t(k)] = (q + 2 * r + (n - 3) * at(int32_t(v), k)) / n;
      }
    }
  }
  if (scheme != FT_SCHEME_LOOP) return out;
  std::vector<std::vector<int32_t>> old_ends(fine.vertex_count());
  first = 0;
  for (int32_t n : fine.face_sizes) {
    const int32_t* f = &fine.face_indices[first];
    for (int32_t i = 0; i < n; ++i) {
      const int32_t a = f[i], b = f[(i + 1) % n];
      if (size_t(a) >= old_count && size_t(b) < old_count) old_ends[size_t(a)].push_back(b);
    }
    first += size_t(n);
  }
  for (size_t e = old_count; e < fine.vertex_count(); ++e) {
    std::set<int32_t> ends(old_ends[e].begin(), old_ends[e].end());
    EXPECT_EQ(ends.size(), 2u) << "new vertex " << e;
    if (ends.size() != 2) continue;
    const int32_t a = *ends.begin(), b = *ends.rbegin();
    const std::vector<int32_t>& cd = opposite[{a, b}];
    EXPECT_EQ(cd.size(), 2u) << "coarse edge " << a << "-" << b;
    if (cd.size() != 2) continue;
    for (int k = 0; k < 3; ++k)
      out[3 * e + size_t(k)] = 0.375 * (at(a, k) + at(b, k)) + 0.125 * (at(cd[0], k) + at(cd[1], k));
  }
  return out;
}

void expect_error(const std::function<void()>& f, ft_status status, const std::string& fragment) {
  try {
    f();
    ADD_FAILURE() << "expected an error containing '" << fragment << "'";
  } catch (const Error& e) {
    EXPECT_EQ(e.status(), status) << e.what();
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

// ---------------------------------------------------------------------------

// Zero displacement is plain subdivision, checked against what the schemes'
// limit surfaces are, without OpenSubdiv: on a regular patch the
// Catmull-Clark limit is the uniform bicubic B-spline of the control net, the
// Loop limit the quartic three-direction box spline, and bilinear refinement
// stays on the bilinear patches. Refinement must not move a limit surface,
// so the limit of the level-k net (its regular limit stencil at each vertex)
// must equal the base net's surface at the same parameters.

// A regular n x n grid: vertex (i, j) at x = i, y = j, a rough z; quads, or
// each quad cut along its (i, j)-(i+1, j+1) diagonal (every inner vertex of
// valence 6, the three-direction mesh of the box spline).
Mesh grid_mesh(int n, bool triangles) {
  Mesh m;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      m.positions.insert(m.positions.end(),
                         {float(i), float(j), float(std::sin(1.7 * i + 0.3 * j * j) + 0.5 * std::cos(2.3 * j - i))});
  auto at = [n](int i, int j) { return int32_t(j * n + i); };
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      const int32_t a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
      if (triangles) {
        m.face_sizes.insert(m.face_sizes.end(), {3, 3});
        m.face_indices.insert(m.face_indices.end(), {a, b, c, a, c, d});
      } else {
        m.face_sizes.push_back(4);
        m.face_indices.insert(m.face_indices.end(), {a, b, c, d});
      }
    }
  return m;
}

// The level-k vertices of a refined grid of side n by lattice position
// (i, j) = 2^k (x, y): the schemes reproduce the linear x and y exactly, so
// each vertex sits on the finer lattice and no two share a spot (checked for
// the vertices whose x and y lie `margin` or more inside the grid, the others
// left out: Loop's boundary rule rounds the corners where two triangles meet).
std::map<std::pair<int, int>, std::array<double, 3>> by_lattice(const Mesh& out, int level, int n = 0,
                                                                 double margin = 0) {
  std::map<std::pair<int, int>, std::array<double, 3>> grid;
  const double scale = std::ldexp(1.0, level);
  for (size_t v = 0; v < out.vertex_count(); ++v) {
    const auto p = out.vertex(v);
    const int i = int(std::lround(p[0] * scale)), j = int(std::lround(p[1] * scale));
    if (margin > 0 && std::min({p[0], p[1], n - 1 - p[0], n - 1 - p[1]}) < margin) continue;
    EXPECT_NEAR(p[0] * scale, i, 1e-4) << "vertex " << v;
    EXPECT_NEAR(p[1] * scale, j, 1e-4) << "vertex " << v;
    EXPECT_TRUE(grid.emplace(std::pair{i, j}, std::array<double, 3>{p[0], p[1], p[2]}).second)
        << "two vertices at lattice point " << i << ", " << j;
  }
  return grid;
}

// The centred uniform cubic B-spline (support -2..2).
double bspline(double t) {
  t = std::abs(t);
  if (t >= 2) return 0;
  if (t >= 1) return (2 - t) * (2 - t) * (2 - t) / 6;
  return (4 - 6 * t * t + 3 * t * t * t) / 6;
}

TEST(Fractalize, ZeroSigmaCatmullClarkStaysOnTheBicubicBSplineLimit) {
  const int n = 9;
  const Mesh base = grid_mesh(n, false);
  // The base net's surface: sum of P_ij B(s - i) B(t - j); over the faces not
  // touching the boundary (1 <= s, t <= n - 2) it is the Catmull-Clark limit.
  auto surface = [&](double s, double t) {
    std::array<double, 3> q{};
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const double w = bspline(s - i) * bspline(t - j);
        for (int c = 0; c < 3; ++c) q[size_t(c)] += w * base.positions[size_t(3 * (j * n + i) + c)];
      }
    return q;
  };
  for (int level = 1; level <= 3; ++level) {
    const Mesh out = subdiv::fractalize(base, params(level, 0.0, FT_SCHEME_CATMARK));
    const int side = ((n - 1) << level) + 1;
    ASSERT_EQ(out.face_count(), base.face_count() << (2 * level));
    const auto grid = by_lattice(out, level);
    ASSERT_EQ(grid.size(), size_t(side * side));
    const double h = std::ldexp(1.0, -level);
    int checked = 0;
    for (int j = 1; j + 1 < side; ++j)
      for (int i = 1; i + 1 < side; ++i) {
        if (i * h < 1 || i * h > n - 2 || j * h < 1 || j * h > n - 2) continue;
        // The regular limit stencil: (1 4 1) x (1 4 1) / 36.
        std::array<double, 3> limit{};
        for (int dj = -1; dj <= 1; ++dj)
          for (int di = -1; di <= 1; ++di) {
            const double w = (di ? 1 : 4) * (dj ? 1 : 4) / 36.0;
            const auto& q = grid.at({i + di, j + dj});
            for (int c = 0; c < 3; ++c) limit[size_t(c)] += w * q[size_t(c)];
          }
        const auto want = surface(i * h, j * h);
        for (int c = 0; c < 3; ++c)
          ASSERT_NEAR(limit[size_t(c)], want[size_t(c)], 2e-5) << "level " << level << " at " << i << ", " << j;
        ++checked;
      }
    EXPECT_EQ(checked, (((n - 3) << level) + 1) * (((n - 3) << level) + 1));
    // The boundary (VTX_BOUNDARY_EDGE_AND_CORNER): corners stay put and each
    // edge's limit is the cubic B-spline curve of its boundary vertices, whose
    // limit stencil is (1 4 1) / 6.
    for (int c = 0; c < 3; ++c) EXPECT_EQ(grid.at({0, 0})[size_t(c)], base.positions[size_t(c)]);
    for (int i = 1; i + 1 < side; ++i) {
      if (i * h < 1 || i * h > n - 2) continue;
      double limit = 0, want = 0;
      for (int di = -1; di <= 1; ++di) limit += (di ? 1 : 4) / 6.0 * grid.at({i + di, 0})[2];
      for (int k = 0; k < n; ++k) want += bspline(i * h - k) * base.positions[size_t(3 * k + 2)];
      ASSERT_NEAR(limit, want, 2e-5) << "boundary, level " << level << " at " << i;
    }
  }
}

TEST(Fractalize, ZeroSigmaLoopStaysOnTheBoxSplineLimit) {
  // The box spline's limit stencil at a vertex of valence 6 (Loop's
  // chi = 1 / (3 / (8 beta) + 6) with beta = 1/16): 1/2 itself, 1/12 each
  // neighbour along (1, 0), (0, 1), (1, 1) and back.
  const int dirs[6][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}, {1, 1}, {-1, -1}};
  auto limit_at = [&](const auto& grid, int i, int j, int step) {
    std::array<double, 3> q = grid.at({i, j});
    for (double& x : q) x *= 0.5;
    for (const auto& d : dirs) {
      const auto& r = grid.at({i + step * d[0], j + step * d[1]});
      for (int c = 0; c < 3; ++c) q[size_t(c)] += r[size_t(c)] / 12;
    }
    return q;
  };
  const int n = 9;
  const Mesh base = grid_mesh(n, true);
  const auto base_grid = by_lattice(base, 0);
  // The level-1 net of the box spline's own two-scale rules (independent of
  // OpenSubdiv): an old vertex 5/8 itself + 1/16 each neighbour; a new one on
  // edge a-b 3/8 (a + b) + 1/8 the two opposite vertices.
  std::map<std::pair<int, int>, std::array<double, 3>> one;
  for (int j = 1; j + 1 < n; ++j)
    for (int i = 1; i + 1 < n; ++i) {
      std::array<double, 3> q = base_grid.at({i, j});
      for (double& x : q) x *= 0.625;
      for (const auto& d : dirs)
        for (int c = 0; c < 3; ++c) q[size_t(c)] += base_grid.at({i + d[0], j + d[1]})[size_t(c)] / 16;
      one[{2 * i, 2 * j}] = q;
    }
  // An edge (a, a + e) has opposite vertices a + f and a + e - f for the two
  // directions f that make triangles with e.
  const int edges[3][3][2] = {{{1, 0}, {1, 1}, {0, -1}}, {{0, 1}, {1, 1}, {-1, 0}}, {{1, 1}, {1, 0}, {0, 1}}};
  for (int j = 1; j + 2 < n; ++j)
    for (int i = 1; i + 2 < n; ++i)
      for (const auto& e : edges) {
        std::array<double, 3> q{};
        const auto &a = base_grid.at({i, j}), &b = base_grid.at({i + e[0][0], j + e[0][1]});
        const auto &c1 = base_grid.at({i + e[1][0], j + e[1][1]}), &c2 = base_grid.at({i + e[2][0], j + e[2][1]});
        for (int c = 0; c < 3; ++c)
          q[size_t(c)] = 0.375 * (a[size_t(c)] + b[size_t(c)]) + 0.125 * (c1[size_t(c)] + c2[size_t(c)]);
        one[{2 * i + e[0][0], 2 * j + e[0][1]}] = q;
      }
  for (int level = 1; level <= 3; ++level) {
    const Mesh out = subdiv::fractalize(base, params(level, 0.0, FT_SCHEME_LOOP));
    ASSERT_EQ(out.face_count(), base.face_count() << (2 * level));
    const auto grid = by_lattice(out, level, n, 1.0);
    const int side = ((n - 1) << level) + 1, inner = ((n - 3) << level) + 1;
    ASSERT_EQ(out.vertex_count(), size_t(side * side));
    ASSERT_EQ(grid.size(), size_t(inner * inner));
    const int to_one = 1 << (level - 1);  // lattice steps from a level-1 point to the next
    int checked = 0;
    // Away from the boundary (2 base steps): the limit at the level-1 net's
    // points, from the level-k net, against the same limit from the level-1 net.
    for (int j = 4; j <= 2 * (n - 3); ++j)
      for (int i = 4; i <= 2 * (n - 3); ++i) {
        if (!one.count({i, j}) || !one.count({i + 1, j + 1}) || !one.count({i - 1, j - 1}) ||
            !one.count({i + 1, j}) || !one.count({i - 1, j}) || !one.count({i, j + 1}) || !one.count({i, j - 1}))
          continue;
        const auto got = limit_at(grid, i * to_one, j * to_one, 1);
        const auto want = limit_at(one, i, j, 1);
        for (int c = 0; c < 3; ++c)
          ASSERT_NEAR(got[size_t(c)], want[size_t(c)], 2e-5) << "level " << level << " at " << i << ", " << j;
        if (i % 2 == 0 && j % 2 == 0) {  // a base vertex: its limit from the base net too
          const auto from_base = limit_at(base_grid, i / 2, j / 2, 1);
          for (int c = 0; c < 3; ++c) ASSERT_NEAR(got[size_t(c)], from_base[size_t(c)], 2e-5);
        }
        ++checked;
      }
    EXPECT_GE(checked, 60);
  }
}

TEST(Fractalize, ZeroSigmaBilinearStaysOnTheBilinearPatches) {
  const int n = 5;
  const Mesh base = grid_mesh(n, false);
  for (int level = 1; level <= 3; ++level) {
    const Mesh out = subdiv::fractalize(base, params(level, 0.0, FT_SCHEME_BILINEAR));
    const auto grid = by_lattice(out, level);
    const int side = ((n - 1) << level) + 1;
    ASSERT_EQ(grid.size(), size_t(side * side));
    for (const auto& [ij, q] : grid) {
      const double s = std::ldexp(double(ij.first), -level), t = std::ldexp(double(ij.second), -level);
      const int i = std::min(int(s), n - 2), j = std::min(int(t), n - 2);
      const double fs = s - i, ft = t - j;
      auto z = [&](int a, int b) { return double(base.positions[size_t(3 * (b * n + a) + 2)]); };
      const double want = (1 - fs) * (1 - ft) * z(i, j) + fs * (1 - ft) * z(i + 1, j) + (1 - fs) * ft * z(i, j + 1) +
                          fs * ft * z(i + 1, j + 1);
      ASSERT_NEAR(q[2], want, 1e-5) << "level " << level << " at " << ij.first << ", " << ij.second;
    }
  }
}

// The displacement added at level k is measured from the outside: the output
// of a run with k - 1 levels is the level k - 1 stage of a run with k levels
// (the random numbers are keyed by (level, vertex)), so
//   D_k = fractalize(k levels) - plain_refinement(fractalize(k - 1 levels)).
// Its RMS over the vertices new at level k should be sigma 2^(-kH).
//
// Tolerance: D_k = sigma 2^(-kH) g n with unit normals n and g ~ N(0,1)
// independent, so RMS_k^2 / (sigma 2^(-kH))^2 is a mean of n_k squared
// normals; its relative standard error is sqrt(2 / n_k), that of RMS_k is
// 1 / sqrt(2 n_k), that of log2 RMS_k is 1 / (sqrt(2 n_k) ln 2). For the
// icosahedron under Loop, n_k = 30 * 4^(k-1) new (edge) vertices: 480, 1920,
// 7680, 30720, 122880 for k = 3..7, giving standard errors 0.047, 0.023,
// 0.012, 0.006, 0.003. The ordinary least-squares slope over k = 3..7
// (centred x = -2..2, Sxx = 10) has standard error
// sqrt(sum x^2 se^2) / Sxx = 0.0096; we allow 0.05 (> 5 standard errors).
// The level-3 RMS alone is checked against sigma 2^(-3H) within 5 * 0.047.
TEST(Fractalize, DisplacementRmsFallsAsTwoToTheMinusKH) {
  const Mesh ico = icosahedron();
  for (double H : {0.3, 0.9}) {
    ft_fractalize_params p = params(2, 0.5, FT_SCHEME_LOOP);
    p.hurst = H;
    Mesh prev = subdiv::fractalize(ico, p);
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (int k = 3; k <= 7; ++k) {
      p.levels = k;
      const Mesh cur = subdiv::fractalize(ico, p);
      const std::vector<double> plain = plain_refinement(prev, cur, FT_SCHEME_LOOP);
      const size_t old_count = prev.vertex_count();
      ASSERT_EQ(cur.positions.size(), plain.size());
      double sum2 = 0;
      size_t n = 0;
      for (size_t v = 0; v < cur.vertex_count(); ++v) {
        double d2 = 0;
        for (int c = 0; c < 3; ++c) d2 += std::pow(double(cur.positions[3 * v + c]) - plain[3 * v + c], 2);
        if (v < old_count) {
          // Zero but for float rounding (1e-7 of a unit sphere; level 7's
          // displacements are 1e-3 and more).
          ASSERT_LT(d2, 1e-11) << "Voss moved vertex " << v << ", a child of an old vertex, at level " << k;
        } else {
          sum2 += d2, ++n;
        }
      }
      ASSERT_EQ(n, 30u << (2 * (k - 1)));
      const double rms = std::sqrt(sum2 / double(n));
      if (k == 3) {
        EXPECT_NEAR(std::log2(rms / (0.5 * std::pow(2.0, -3 * H))), 0.0, 5 * 0.047);
      }
      const double x = k, y = std::log2(rms);
      sx += x, sy += y, sxx += x * x, sxy += x * y;
      prev = cur;
    }
    const double slope = (5 * sxy - sx * sy) / (5 * sxx - sx * sx);
    EXPECT_NEAR(slope, -H, 0.05) << "H = " << H;
  }
}

TEST(Fractalize, AdditionsMoveOldVerticesToo) {
  const Mesh c = cube();
  ft_fractalize_params p = params(1, 0.3);
  p.mode = FT_FRACTALIZE_ADDITIONS;
  const Mesh one = subdiv::fractalize(c, p);
  p.levels = 2;
  const Mesh two = subdiv::fractalize(c, p);
  const std::vector<double> plain = plain_refinement(one, two, FT_SCHEME_CATMARK);
  int moved_old = 0;
  for (size_t v = 0; v < one.vertex_count(); ++v) {
    double d2 = 0;
    for (int k = 0; k < 3; ++k) d2 += std::pow(two.positions[3 * v + size_t(k)] - plain[3 * v + size_t(k)], 2);
    moved_old += d2 > 1e-11;  // more than float rounding
  }
  EXPECT_EQ(moved_old, int(one.vertex_count()));
}

// Every edge of the output is shared by exactly two faces, walked once in
// each direction: no cracks, orientation kept.
void expect_closed(const Mesh& m) {
  std::map<std::pair<int, int>, int> directed;
  size_t first = 0;
  for (int32_t n : m.face_sizes) {
    for (int32_t i = 0; i < n; ++i)
      ++directed[{m.face_indices[first + i], m.face_indices[first + (i + 1) % n]}];
    first += size_t(n);
  }
  for (const auto& [e, count] : directed) {
    ASSERT_EQ(count, 1) << "edge " << e.first << "-" << e.second;
    ASSERT_EQ(directed.count({e.second, e.first}), 1u) << "edge " << e.first << "-" << e.second << " is open";
  }
  for (float x : m.positions) ASSERT_TRUE(std::isfinite(x));
}

TEST(Fractalize, ClosedInputStaysClosed) {
  for (int mode : {FT_FRACTALIZE_MIDPOINT, FT_FRACTALIZE_ADDITIONS}) {
    ft_fractalize_params p = params(4, 0.3);
    p.mode = mode;
    const Mesh rock = subdiv::fractalize(cube(), p);
    EXPECT_EQ(rock.face_count(), 6u * 256u);
    for (int32_t n : rock.face_sizes) ASSERT_EQ(n, 4);
    expect_closed(rock);
    p.scheme = FT_SCHEME_LOOP;
    const Mesh planet = subdiv::fractalize(icosahedron(), p);
    EXPECT_EQ(planet.face_count(), 20u * 256u);
    for (int32_t n : planet.face_sizes) ASSERT_EQ(n, 3);
    expect_closed(planet);
  }
}

TEST(Fractalize, SameSeedSameBitsOnAnyThreadCount) {
  ft_fractalize_params p = params(5, 0.2, FT_SCHEME_LOOP);
  p.threads = 1;
  const Mesh a = subdiv::fractalize(icosahedron(), p);
  for (int threads : {2, 3, 0}) {
    p.threads = threads;
    const Mesh b = subdiv::fractalize(icosahedron(), p);
    ASSERT_EQ(a.positions.size(), b.positions.size());
    EXPECT_EQ(std::memcmp(a.positions.data(), b.positions.data(), a.positions.size() * sizeof(float)), 0)
        << threads << " threads";
    EXPECT_EQ(a.face_indices, b.face_indices);
  }
  p.seed = 12;
  EXPECT_NE(subdiv::fractalize(icosahedron(), p).positions, a.positions);
}

TEST(Fractalize, FixedBoundaryStaysOnThePlainBoundaryCurve) {
  const Mesh m = mountain();
  const Mesh plain = subdiv::fractalize(m, params(3, 0.0));
  ft_fractalize_params p = params(3, 0.5);
  p.fix_boundary = 1;
  const Mesh fixed = subdiv::fractalize(m, p);
  // Boundary of the 6 x 6 quad grid refined 3 times: a 49 x 49 vertex grid
  // whose border is at |x| = 6 or |y| = 6 in the plain result.
  int boundary = 0, moved_inside = 0;
  for (size_t v = 0; v < plain.vertex_count(); ++v) {
    const auto q = plain.vertex(v);
    if (std::fabs(std::fabs(q[0]) - 6) < 1e-5 || std::fabs(std::fabs(q[1]) - 6) < 1e-5) {
      ++boundary;
      EXPECT_EQ(fixed.vertex(v), q) << "boundary vertex " << v;
    } else {
      moved_inside += fixed.vertex(v) != q;
    }
  }
  EXPECT_EQ(boundary, 4 * 48);
  EXPECT_GT(moved_inside, 1000);
  p.fix_boundary = 0;
  const Mesh free = subdiv::fractalize(m, p);
  int moved_boundary = 0;
  for (size_t v = 0; v < plain.vertex_count(); ++v) {
    const auto q = plain.vertex(v);
    if (std::fabs(std::fabs(q[0]) - 6) < 1e-5 || std::fabs(std::fabs(q[1]) - 6) < 1e-5)
      moved_boundary += free.vertex(v) != q;
  }
  EXPECT_GT(moved_boundary, 100);
}

TEST(Fractalize, WeightsScaleTheDisplacement) {
  const Mesh c = cube();
  const Mesh plain = subdiv::fractalize(c, params(3, 0.0));
  std::vector<float> w(c.vertex_count(), 0.0f);
  ft_fractalize_params p = params(3, 0.4);
  p.weights = w.data();
  const Mesh masked = subdiv::fractalize(c, p);
  for (size_t i = 0; i < plain.positions.size(); ++i) ASSERT_NEAR(masked.positions[i], plain.positions[i], 1e-6f);
  // Weight 1 everywhere is the unweighted result (the interpolated weight
  // is 1 up to float rounding of the subdivision masks).
  std::fill(w.begin(), w.end(), 1.0f);
  const Mesh ones = subdiv::fractalize(c, p);
  p.weights = nullptr;
  const Mesh unweighted = subdiv::fractalize(c, p);
  for (size_t i = 0; i < ones.positions.size(); ++i) ASSERT_NEAR(ones.positions[i], unweighted.positions[i], 1e-5f);
  // A mask on the (1, 1, 1) corner only: the weight primvar is zero on the
  // faces away from it, and what moves there is only the smoothing of
  // displaced neighbours, so the far octant moves far less than the near one.
  std::fill(w.begin(), w.end(), 0.0f);
  w[6] = 1.0f;
  p.weights = w.data();
  const Mesh corner = subdiv::fractalize(c, p);
  double near_d = 0, far_d = 0;
  for (size_t v = 0; v < plain.vertex_count(); ++v) {
    const auto q = plain.vertex(v), r = corner.vertex(v);
    const double d = std::fabs(q[0] - r[0]) + std::fabs(q[1] - r[1]) + std::fabs(q[2] - r[2]);
    if (q[0] + q[1] + q[2] > 1.0) near_d += d;
    if (q[0] + q[1] + q[2] < -1.0) far_d += d;
  }
  EXPECT_GT(near_d, 20 * far_d);
}

TEST(Fractalize, EdgeLengthScalingMakesTheResultScaleFree) {
  Mesh small = cube(), big = cube();
  for (float& x : big.positions) x *= 8.0f;  // a power of two: exact
  ft_fractalize_params p = params(3, 0.2);
  p.scale_by_edge_length = 1;
  const Mesh a = subdiv::fractalize(small, p), b = subdiv::fractalize(big, p);
  for (size_t i = 0; i < a.positions.size(); ++i) ASSERT_NEAR(8.0f * a.positions[i], b.positions[i], 1e-4f);
}

TEST(Fractalize, RejectsBadMeshesNamingTheFace) {
  auto run = [](const Mesh& m, int scheme = FT_SCHEME_CATMARK) {
    return [m, scheme] { subdiv::fractalize(m, params(2, 0.1, scheme)); };
  };
  Mesh m = cube();
  m.face_indices[5] = 8;
  expect_error(run(m), FT_ERR_INVALID_ARGUMENT, "face 1 refers to vertex 8");
  m = cube();
  m.face_indices[5] = 4;  // face 1 = 5 5 7 8 -> vertex 4 twice
  expect_error(run(m), FT_ERR_INVALID_ARGUMENT, "face 1 uses vertex 4 twice");
  m = cube();
  m.face_sizes = {4, 4, 4, 4, 4, 2, 2};
  expect_error(run(m), FT_ERR_INVALID_ARGUMENT, "face 5 has 2 vertices");
  m = cube();
  std::swap(m.face_indices[1], m.face_indices[3]);  // face 0 flipped
  expect_error(run(m), FT_ERR_INVALID_ARGUMENT, "oriented consistently");
  m = cube();
  m.positions[3 * 7] = NAN;
  expect_error(run(m), FT_ERR_INVALID_ARGUMENT, "vertex 7 has a non-finite coordinate");
  m = cube();
  for (int i : {0, 1, 2, 3}) m.positions[3 * size_t(i) + 2] = 0, m.positions[3 * size_t(i) + 1] = 0;
  expect_error(run(m), FT_ERR_INVALID_ARGUMENT, "face 0 has zero area");
  expect_error(run(cube(), FT_SCHEME_LOOP), FT_ERR_INVALID_ARGUMENT, "face 0 has 4 vertices; Loop");
  m = cube();
  m.crease_pairs = {0, 6};
  m.crease_sharpness = {2.0f};
  expect_error(run(m), FT_ERR_INVALID_ARGUMENT, "not the ends of an edge");
  m.crease_pairs = {0, 1};
  m.crease_sharpness = {11.0f};
  expect_error(run(m), FT_ERR_INVALID_ARGUMENT, "sharpness 11");
  m = Mesh{};
  expect_error(run(m), FT_ERR_INVALID_ARGUMENT, "no faces");
  // three faces on one edge: a fin added to the cube's edge 0-1
  m = cube();
  m.positions.insert(m.positions.end(), {0, -3, -3});
  m.face_sizes.push_back(3);
  m.face_indices.insert(m.face_indices.end(), {0, 1, 8});
  expect_error(run(m), FT_ERR_INVALID_ARGUMENT, "face 6 is the offending face");
}

TEST(Fractalize, RejectsBadParameters) {
  const Mesh c = cube();
  auto with = [&c](auto change) {
    return [&c, change] {
      ft_fractalize_params p = params(2, 0.1);
      change(p);
      subdiv::fractalize(c, p);
    };
  };
  expect_error(with([](auto& p) { p.levels = 0; }), FT_ERR_INVALID_ARGUMENT, "levels must be in 1..10");
  expect_error(with([](auto& p) { p.levels = 11; }), FT_ERR_INVALID_ARGUMENT, "levels must be in 1..10");
  expect_error(with([](auto& p) { p.hurst = 1.5; }), FT_ERR_INVALID_ARGUMENT, "hurst must be in [0, 1]");
  expect_error(with([](auto& p) { p.sigma = -1; }), FT_ERR_INVALID_ARGUMENT, "sigma must be");
  expect_error(with([](auto& p) { p.sigma = NAN; }), FT_ERR_INVALID_ARGUMENT, "got NaN");
  expect_error(with([](auto& p) { p.scheme = 7; }), FT_ERR_INVALID_ARGUMENT, "scheme");
  expect_error(with([](auto& p) { p.mode = -1; }), FT_ERR_INVALID_ARGUMENT, "mode");
  expect_error(with([](auto& p) { p.threads = -1; }), FT_ERR_INVALID_ARGUMENT, "threads");
  expect_error(with([](auto& p) { p.struct_size = 8; }), FT_ERR_INVALID_ARGUMENT, "struct_size");
}

TEST(Fractalize, RefusesResultsAboveTheMemoryCapBeforeAllocating) {
  set_memory_cap(64 << 20);
  expect_error([] { subdiv::fractalize(cube(), params(10, 0.1)); }, FT_ERR_TOO_LARGE, "fractalizing to 10 levels");
  set_memory_cap(0);
}

TEST(Fractalize, HonoursCreases) {
  // An infinitely sharp crease loop around the cube's top face cuts it off
  // from the smoothing: the crease vertices follow the crease rule within
  // z = 1 and the face inside stays flat, so the whole refined top face,
  // (2^3 + 1)^2 vertices after 3 levels, stays at z = 1. Without the crease
  // Catmull-Clark pulls every vertex below z = 1.
  Mesh c = cube();
  auto top = [](const Mesh& m) {
    int n = 0;
    for (size_t v = 0; v < m.vertex_count(); ++v) n += m.vertex(v)[2] == 1.0f;
    return n;
  };
  EXPECT_EQ(top(subdiv::fractalize(c, params(3, 0.0))), 0);
  c.crease_pairs = {4, 5, 5, 6, 6, 7, 7, 4};
  c.crease_sharpness = {10, 10, 10, 10};
  EXPECT_EQ(top(subdiv::fractalize(c, params(3, 0.0))), 81);
}

// ---------------------------------------------------------------------------

TEST(ObjIo, RoundTripIsExact) {
  ft_fractalize_params p = params(2, 0.3);
  Mesh m = subdiv::fractalize(cube(), p);
  m.crease_pairs = {m.face_indices[0], m.face_indices[1]};
  m.crease_sharpness = {2.5f};
  m.corner_vertices = {3};
  m.corner_sharpness = {10.0f};
  const fs::path dir = fs::temp_directory_path() / ("ft_subdiv_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string path = (dir / "rock.obj").string();
  io::write_obj(m, path, "a comment\nwith a newline");
  const Mesh back = io::read_obj(path);
  EXPECT_EQ(back.positions, m.positions);
  EXPECT_EQ(back.face_sizes, m.face_sizes);
  EXPECT_EQ(back.face_indices, m.face_indices);
  EXPECT_EQ(back.crease_pairs, m.crease_pairs);
  EXPECT_EQ(back.crease_sharpness, m.crease_sharpness);
  EXPECT_EQ(back.corner_vertices, m.corner_vertices);
  EXPECT_EQ(back.corner_sharpness, m.corner_sharpness);
  for (const auto& e : fs::directory_iterator(dir))
    EXPECT_EQ(e.path().filename(), "rock.obj") << "a temporary file was left behind";
  fs::remove_all(dir);
}

TEST(ObjIo, ReadsPolygonsFromAllShapes) {
  const Mesh m = io::decode_obj("o a\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nf 1 2 3 4\no b\nf 2 5 3\n");
  EXPECT_EQ(m.vertex_count(), 5u);
  EXPECT_EQ(m.face_sizes, (std::vector<int32_t>{4, 3}));
  EXPECT_EQ(m.face_indices, (std::vector<int32_t>{0, 1, 2, 3, 1, 4, 2}));
}

TEST(ObjIo, ReportsMissingAndFacelessFiles) {
  expect_error([] { io::read_obj("/nonexistent/mesh.obj"); }, FT_ERR_IO, "/nonexistent/mesh.obj");
  expect_error([] { io::decode_obj("v 0 0 0\nv 1 0 0\n", "points.obj"); }, FT_ERR_FORMAT, "points.obj' has no faces");
}

// Lines tinyobjloader used to take on trust (see obj_io.cpp): each now a
// clear FT_ERR_FORMAT naming the line, where it was undefined behaviour, an
// infinite vertex or a silently wrong face.
TEST(ObjIo, RefusesNumbersAndFacesTheReaderCannotHold) {
  const std::string quad = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";
  expect_error([&] { io::decode_obj("v 0 0 1e39\n" + quad + "f 2 3 4\n", "big.obj"); }, FT_ERR_FORMAT,
               "'big.obj': line 1: '1e39' is beyond the float range");
  expect_error([&] { io::decode_obj(quad + "f 1 2 99999999999\n", "idx.obj"); }, FT_ERR_FORMAT,
               "line 5: '99999999999' is not an integer in the 32-bit range");
  expect_error([&] { io::decode_obj(quad + "f 1 0 2\n", "zero.obj"); }, FT_ERR_FORMAT, "line 5: vertex index 0");
  expect_error([&] { io::decode_obj("v 0 nan 0\n" + quad + "f 2 3 4\n"); }, FT_ERR_FORMAT, "'nan' is not a finite number");
  expect_error([&] { io::decode_obj(quad + "f 1 2 3\nt crease 2/1/0 0 1\n"); }, FT_ERR_FORMAT, "line 6: the tag's counts");
  std::string ring;
  for (int i = 0; i < 300; ++i) ring += "v " + std::to_string(std::cos(i * 0.0209)) + " " + std::to_string(std::sin(i * 0.0209)) + " 0\n";
  ring += "f";
  for (int i = 1; i <= 300; ++i) ring += " " + std::to_string(i);
  expect_error([&] { io::decode_obj(ring + "\n"); }, FT_ERR_FORMAT, "a face of 300 vertices; at most 255");
}

TEST(ObjIo, IgnoresWhatItDoesNotUseAndKeepsWhatItDoes) {
  // Normals, texture coordinates, weights (the fuzzer's `vw` of 1e300),
  // groups, materials; v/vt/vn faces; comments; CRLF; a '+' sign; w.
  const Mesh m = io::decode_obj(
      "# a comment\r\nmtllib x.mtl\r\no a\r\nv 0 0 0 1\r\nv +1 0 0\r\nv 1 1 0 # corner\r\nvn 0 0 1\r\n"
      "vt 0.5 0.5\r\nvw 1 0333333333333333333333333333333333333333333333 00\r\nusemtl m\r\ns 1\r\n"
      "f 1/1/1 2/1/1 -1/1/1\r\nl 1 2\r\nt crease 2/1/0 0 1 2.5\r\nt corner 1/1/0 2 4\r\nt interpolateboundary 1/0/0 1\r\n"
      "v 1e-300 -2e-60 3.5\r\n");  // underflows are zero, as in a float
  EXPECT_EQ(m.positions, (std::vector<float>{0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 0, 3.5f}));
  EXPECT_EQ(m.face_sizes, (std::vector<int32_t>{3}));
  EXPECT_EQ(m.face_indices, (std::vector<int32_t>{0, 1, 2}));
  EXPECT_EQ(m.crease_pairs, (std::vector<int32_t>{0, 1}));
  EXPECT_EQ(m.crease_sharpness, (std::vector<float>{2.5f}));
  EXPECT_EQ(m.corner_vertices, (std::vector<int32_t>{2}));
  EXPECT_EQ(m.corner_sharpness, (std::vector<float>{4.0f}));
}

TEST(PovMesh2, IdentifiersAreValidAndNeverKeywords) {
  EXPECT_EQ(pov::identifier("FT_Rock"), "FT_Rock");
  EXPECT_EQ(pov::identifier("sphere"), "FT_sphere");
  EXPECT_EQ(pov::identifier("3 rocks/big"), "FT__3_rocks_big");
  EXPECT_EQ(pov::identifier("Fels\xc3\xa4"), "Fels__");
  EXPECT_EQ(pov::identifier(""), "FT__");
}

TEST(PovMesh2, TriangulatesAndWritesOneNormalPerVertex) {
  const std::string s = pov::encode_mesh2(cube(), "Cube");
  EXPECT_NE(s.find("#declare Cube = mesh2 {"), std::string::npos);
  EXPECT_NE(s.find("vertex_vectors {\n    8,"), std::string::npos);
  EXPECT_NE(s.find("normal_vectors {\n    8,"), std::string::npos);
  EXPECT_NE(s.find("face_indices {\n    12,"), std::string::npos);
  // the (1, 1, 1) corner's normal is the diagonal
  EXPECT_NE(s.find("<0.5773503, 0.5773503, 0.5773503>"), std::string::npos) << s;
}

// Real consumers: the CLI writes OBJ and mesh2, POV-Ray renders the mesh2.
TEST(FractalizeCli, WritesObjAndAPovMeshThatPovRayRenders) {
  const fs::path dir = fs::temp_directory_path() / ("ft_subdiv_cli_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string obj = (dir / "rock.obj").string(), pov = (dir / "rock.inc").string();
  const std::string cmd = std::string(FT_CLI_PATH) + " fractalize --in " + kMeshes +
                          "cube.obj --levels 3 --hurst 0.7 --sigma 0.3 --scheme catmark --seed 5 --out " + obj +
                          " --pov " + pov + " --pov-name Rock";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  const Mesh m = io::read_obj(obj);
  EXPECT_EQ(m.face_count(), 6u * 64u);
  expect_closed(m);
  const std::string bad = std::string(FT_CLI_PATH) + " fractalize --in " + kMeshes +
                          "cube.obj --scheme loop --out " + obj + " 2>" + (dir / "err.txt").string();
  EXPECT_NE(std::system(bad.c_str()), 0);
  EXPECT_NE(io::read_file((dir / "err.txt").string()).find("face 0 has 4 vertices; Loop"), std::string::npos);

  if (std::system("povray --version >/dev/null 2>&1") != 0) GTEST_SKIP() << "povray not installed";
  const std::string scene = (dir / "scene.pov").string(), png = (dir / "rock.png").string();
  io::write_file_atomically(scene, "#version 3.7;\n#include \"" + pov +
                                   "\"\ncamera { location <3, 2, -4> look_at 0 }\n"
                                   "light_source { <5, 8, -6> color rgb 1 }\n"
                                   "object { Rock pigment { color rgb 0.6 } }\n");
  const std::string render = "povray +W48 +H36 -D -GA +O" + png + " " + scene + " >/dev/null 2>&1";
  ASSERT_EQ(std::system(render.c_str()), 0) << render;
  EXPECT_GT(fs::file_size(png), 100u);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace ft
