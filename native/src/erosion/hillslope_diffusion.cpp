// SPDX-License-Identifier: GPL-3.0-or-later
// Hillslope diffusion dz/dt = D laplacian(z), one backward-Euler step split
// into an implicit sweep along x and one along y (alternating directions):
// unconditionally stable, each sweep a tridiagonal solve per line.
// The matrix is the same for every line, so its elimination factors are
// computed once, and the sweep along y runs the Thomas algorithm on whole
// rows at a time (contiguous, vectorised, columns split among threads).
// A bounded grid's edges are closed to creep (no flux across them): its edge
// cells creep with their neighbours inside like any other. Held fixed, the
// edge row kept the input's rough heights beside the smoothed rows inside, a
// one-cell fringe at the model's own grid (p99 |Laplacian| of the border
// 1.2-2.2x the interior's on fBm 257^2). Water still leaves there: the
// landscape model keeps the edge cells that gather water from rising
// (kOutletCells). Periodic grids solve the cyclic system by
// Sherman-Morrison, in double: in float its
// correction cancels (1 + v.z is about det A / det A', tiny against its
// terms once r is large), and a 13 x 3 torus at r = 8e13 turned into NaN
// (the erosion fuzzer, 2026-11-27), a 4097-sample line at r = 1e4 lost 1e-4
// of its mean. Where even double cannot resolve the slowest mode (r times
// its eigenvalue above 1e8) every mode is damped below float's resolution
// and a line becomes its mean.
//
// With a weight per cell (the erosion mask) the flux between two neighbours
// is D x the smaller of their weights x their difference: creep acts only
// where the mask lets it, and a cell of weight 0 keeps its height. In flux
// form it moves material without making or losing any (every line keeps
// its sum). Each line then has its own tridiagonal, eliminated in double in a form without
// cancellation, and a periodic line adds its wrap edge by Sherman-Morrison
// as that edge's own rank-one term, whose denominator is at least 1 (see
// WeightedLines).
#include <algorithm>
#include <cmath>
#include <vector>

#include "erosion/erosion.hpp"

namespace ft::erosion {
namespace {

// Thomas factors of (-r, 1 + 2r, -r) on a line of `len` samples, `cyclic`
// or open (no flux past its ends: the end rows are (1 + r, -r)).
template <class T>
struct LineSolver {
  std::vector<T> a, cp, inv;  // sub-diagonal, modified super-diagonal, 1 / pivot
  std::vector<T> z;           // cyclic only: the solution for the correction vector
  bool cyclic = false;
  T gamma = 0, beta = 0, alpha = 0, z_scale = 0;

  LineSolver(int32_t len, double r, bool is_cyclic) : cyclic(is_cyclic) {
    std::vector<double> aa(len, -r), bb(len, 1 + 2 * r), cc(len, -r);
    if (!cyclic) {
      bb[0] -= r;
      bb[len - 1] -= r;
      cc[len - 1] = 0;
    } else {
      // A = A' + u v^T with u = (gamma, 0.., alpha), v = (1, 0.., beta / gamma).
      alpha = T(-r);  // A[len-1][0]
      beta = T(-r);   // A[0][len-1]
      gamma = T(-bb[0]);
      bb[0] -= gamma;
      bb[len - 1] -= double(alpha) * beta / gamma;
    }
    aa[0] = 0;
    a.assign(aa.begin(), aa.end());
    cp.resize(len);
    inv.resize(len);
    double prev_cp = 0;
    for (int32_t j = 0; j < len; ++j) {
      const double pivot = bb[j] - aa[j] * prev_cp;
      inv[j] = T(1.0 / pivot);
      prev_cp = (j + 1 < len) ? cc[j] / pivot : 0.0;
      cp[j] = T(prev_cp);
    }
    if (cyclic) {
      z.assign(len, T(0));
      z[0] = gamma;
      z[len - 1] = alpha;
      solve_plain(z.data(), 1);
      z_scale = T(1) + z[0] + beta * z[len - 1] / gamma;
    }
  }

  // In place on line[j * stride], j = 0..len-1.
  void solve_plain(T* line, size_t stride) const {
    const int32_t len = int32_t(cp.size());
    line[0] *= inv[0];
    for (int32_t j = 1; j < len; ++j) line[j * stride] = (line[j * stride] - a[j] * line[(j - 1) * stride]) * inv[j];
    for (int32_t j = len - 2; j >= 0; --j) line[j * stride] -= cp[j] * line[(j + 1) * stride];
  }
  void solve(T* line) const {
    solve_plain(line, 1);
    if (cyclic) correct(line, 1, 1);
  }
  // x = y - (v.y / (1 + v.z)) z on `count` adjacent lines.
  void correct(T* lines, size_t stride, size_t count) const {
    const int32_t len = int32_t(cp.size());
    for (size_t c = 0; c < count; ++c) {
      const T fact = (lines[c] + beta * lines[(len - 1) * stride + c] / gamma) / z_scale;
      for (int32_t j = 0; j < len; ++j) lines[j * stride + c] -= fact * z[j];
    }
  }
};

// One step on z (float on bounded grids, double on periodic ones).
template <class T>
void diffuse(const D8Grid& g, T* z, double r) {
  const LineSolver<T> along_x(g.width, r, g.periodic), along_y(g.height, r, g.periodic);
  const size_t w = size_t(g.width);
  // Rows: each is a contiguous line.
#pragma omp parallel for schedule(static)
  for (int32_t y = 0; y < g.height; ++y) along_x.solve(z + y * w);
  // Columns: the Thomas recurrences run over whole row segments.
  const int32_t len = g.height;
  const int32_t block = 256;
  const int32_t blocks = int32_t((w + block - 1) / block);
#pragma omp parallel for schedule(static)
  for (int32_t b = 0; b < blocks; ++b) {
    const size_t x0 = size_t(b) * block, x1 = std::min(w, x0 + block);
    T* base = z + x0;
    const size_t cnt = x1 - x0;
    for (size_t c = 0; c < cnt; ++c) base[c] *= along_y.inv[0];
    for (int32_t j = 1; j < len; ++j) {
      T* row = base + j * w;
      const T* prev = row - w;
      const T aj = along_y.a[j], ij = along_y.inv[j];
      for (size_t c = 0; c < cnt; ++c) row[c] = (row[c] - aj * prev[c]) * ij;
    }
    for (int32_t j = len - 2; j >= 0; --j) {
      T* row = base + j * w;
      const T* next = row + w;
      const T cj = along_y.cp[j];
      for (size_t c = 0; c < cnt; ++c) row[c] -= cj * next[c];
    }
    if (along_y.cyclic) along_y.correct(base, w, cnt);
  }
}

// r times the smallest non-zero eigenvalue of a cyclic line's Laplacian,
// 2 - 2 cos(2 pi / len): how far its slowest mode is damped (by 1 / (1 + it)).
// r times the smallest non-zero eigenvalue of a line's Laplacian: 2 - 2 cos(2 pi / len)
// on a cyclic line, 2 - 2 cos(pi / len) on an open one (no flux past its ends).
double slowest_damping(int32_t len, double r, bool cyclic) {
  return r * (2.0 - 2.0 * std::cos((cyclic ? 2.0 : 1.0) * M_PI / len));
}

// Solves `count` lines side by side (element j of line c at u[j * count + c],
// e likewise), in place, in double:
//   (1 + e[j-1] + e[j]) u_j - e[j-1] u_{j-1} - e[j] u_{j+1} = f_j,
// e[j] the coupling of j and j + 1 (r x the edge's weight); the line is
// open (no flux past its ends) or, `cyclic`, closed by e[len - 1] between
// its last and first samples. The pivots p_j = q_j + c_j are built from their
// surplus q_j = 1 + a_j q_{j-1} / p_{j-1} (a, c: the sub- and
// super-diagonal's magnitudes), a sum of positive terms: the textbook
// b_j - a_j c_{j-1} / p_{j-1} cancels once r is large. The wrap edge is
// A - A_open = e_w (e_0 - e_last)(e_0 - e_last)^T: with v = e_0 - e_last,
// x = y - v.y / (1 + e_w v.A_open^-1 v) e_w A_open^-1 v, and the
// denominator is at least 1 (A_open is positive definite).
struct WeightedLines {
  std::vector<double> u, e, t, w, rho, zero;  // values, couplings, c_j / p_j, the wrap's solve, q / p, 0s

  void solve(int32_t len, int32_t count, bool cyclic) {
    t.resize(u.size());
    rho.assign(size_t(count), 0.0);
    zero.assign(size_t(count), 0.0);
    if (cyclic) {
      w.assign(u.size(), 0.0);
      eliminate<true>(len, count);
    } else {
      eliminate<false>(len, count);
    }
    for (int32_t j = len - 2; j >= 0; --j) {
      const size_t k = size_t(j) * count;
      for (int32_t c = 0; c < count; ++c) u[k + c] += t[k + c] * u[k + count + c];
      if (cyclic)
        for (int32_t c = 0; c < count; ++c) w[k + c] += t[k + c] * w[k + count + c];
    }
    if (!cyclic) return;
    const size_t last = size_t(len - 1) * count;
    std::vector<double>& fact = rho;  // free now
    for (int32_t c = 0; c < count; ++c) fact[c] = (u[c] - u[last + c]) / (1.0 + w[c] - w[last + c]);
    for (int32_t j = 0; j < len; ++j) {
      const size_t k = size_t(j) * count;
      for (int32_t c = 0; c < count; ++c) u[k + c] -= fact[c] * w[k + c];
    }
  }

  // The forward sweep, line by line along j and across the lines at each j
  // (independent, so that loop vectorises); with kWrap also on the right
  // side e_w (e_0 - e_last) of the wrap's solve.
  template <bool kWrap>
  void eliminate(int32_t len, int32_t count) {
    const size_t last = size_t(len - 1) * count;
    for (int32_t j = 0; j < len; ++j) {
      const size_t k = size_t(j) * count;
      const double* a = j > 0 ? e.data() + k - count : zero.data();
      const double* cc = j < len - 1 ? e.data() + k : zero.data();
      const double* up = j > 0 ? u.data() + k - count : zero.data();
      const double* wp = kWrap && j > 0 ? w.data() + k - count : zero.data();
      const double sign = j == 0 ? 1.0 : j == len - 1 ? -1.0 : 0.0;
      double* uj = u.data() + k;
      double* tj = t.data() + k;
      double* wj = kWrap ? w.data() + k : nullptr;
      for (int32_t c = 0; c < count; ++c) {
        const double q = 1.0 + a[c] * rho[c], inv = 1.0 / (q + cc[c]);
        rho[c] = q * inv;
        tj[c] = cc[c] * inv;
        uj[c] = (uj[c] + a[c] * up[c]) * inv;
        if constexpr (kWrap) wj[c] = (sign * e[last + c] + a[c] * wp[c]) * inv;
      }
    }
  }
};

// One step with a weight per cell in [0, 1] (see the file comment). Both
// sweeps take blocks of adjacent lines, copied into WeightedLines side by
// side (the elimination along a single line waits on each division).
void diffuse_weighted(const D8Grid& g, float* z, double r, const float* weight) {
  const int32_t w = g.width, h = g.height;
  // `lines_in_all` lines of `len` samples; sample j of line l is z[l * line + j * step].
  auto sweep = [&](int32_t len, int32_t lines_in_all, size_t line, size_t step) {
    constexpr int32_t kBlock = 32;
    const int32_t blocks = (lines_in_all + kBlock - 1) / kBlock;
#pragma omp parallel
    {
      WeightedLines lines;
#pragma omp for schedule(static)
      for (int32_t b = 0; b < blocks; ++b) {
        const int32_t first = b * kBlock, count = std::min(kBlock, lines_in_all - first);
        lines.u.resize(size_t(len) * count);
        lines.e.resize(size_t(len) * count);
        for (int32_t j = 0; j < len; ++j) {
          const size_t at = size_t(first) * line + size_t(j) * step, next = size_t(first) * line + size_t((j + 1) % len) * step;
          for (int32_t c = 0; c < count; ++c) {
            lines.u[size_t(j) * count + c] = z[at + c * line];
            lines.e[size_t(j) * count + c] = r * double(std::min(weight[at + c * line], weight[next + c * line]));
          }
        }
        lines.solve(len, count, g.periodic);
        for (int32_t j = 0; j < len; ++j)
          for (int32_t c = 0; c < count; ++c) z[size_t(first + c) * line + size_t(j) * step] = float(lines.u[size_t(j) * count + c]);
      }
    }
  };
  // Rows, then columns.
  sweep(w, h, size_t(w), 1);
  sweep(h, w, 1, size_t(w));
}

}  // namespace

void hillslope_diffusion(const D8Grid& g, float* z, double diffusivity_dt, const float* weight) {
  const double r = std::min(diffusivity_dt / (g.spacing * g.spacing), double(kMaxSolveFactor));
  // Weights of 1 everywhere are no mask: the same bits as none.
  if (weight && std::any_of(weight, weight + g.size(), [](float v) { return v < 1.0f; })) {
    diffuse_weighted(g, z, r, weight);
    return;
  }
  // Where r times a line's slowest mode exceeds this, every mode but its
  // mean is damped below float's resolution, and the factors' last pivot
  // (about the line's length, the difference of terms of order r) is lost
  // to rounding: an open line of 17 at r = 1e20 got a pivot of 0 and turned
  // into NaN (the erosion fuzzer). Such a line becomes its mean.
  constexpr double kBeyondFloat = 1e8;
  const bool flat_x = slowest_damping(g.width, r, g.periodic) > kBeyondFloat;
  const bool flat_y = slowest_damping(g.height, r, g.periodic) > kBeyondFloat;
  if (!g.periodic && !flat_x && !flat_y) {
    diffuse(g, z, r);
    return;
  }
  const size_t n = g.size();
  std::vector<double> zd(z, z + n);
  const size_t w = size_t(g.width);
  if (flat_x && flat_y) {
    // Both sweeps flatten their lines: the whole grid becomes its mean.
    double mean = 0;
    for (double v : zd) mean += v;
    std::fill(z, z + n, float(mean / double(n)));
    return;
  }
  if (flat_x) {
    for (int32_t y = 0; y < g.height; ++y) {  // rows become their means, then the columns' solve
      double mean = 0;
      for (size_t x = 0; x < w; ++x) mean += zd[y * w + x];
      std::fill(zd.begin() + y * w, zd.begin() + (y + 1) * w, mean / double(w));
    }
    std::vector<double> col(g.height);
    for (int32_t y = 0; y < g.height; ++y) col[y] = zd[y * w];
    const LineSolver<double> along_y(g.height, r, g.periodic);
    along_y.solve(col.data());
    for (size_t i = 0; i < n; ++i) z[i] = float(col[i / w]);
    return;
  }
  if (flat_y) {
    const LineSolver<double> along_x(g.width, r, g.periodic);
    std::vector<double> mean(w, 0.0);
    for (int32_t y = 0; y < g.height; ++y) along_x.solve(zd.data() + y * w);
    for (size_t i = 0; i < n; ++i) mean[i % w] += zd[i];
    for (size_t i = 0; i < n; ++i) z[i] = float(mean[i % w] / double(g.height));
    return;
  }
  diffuse(g, zd.data(), r);
  for (size_t i = 0; i < n; ++i) z[i] = float(zd[i]);
}

}  // namespace ft::erosion
