// Hillslope diffusion dz/dt = D laplacian(z), one backward-Euler step split
// into an implicit sweep along x and one along y (alternating directions):
// unconditionally stable, each sweep a tridiagonal solve per line.
// The matrix is the same for every line, so its elimination factors are
// computed once, and the sweep along y runs the Thomas algorithm on whole
// rows at a time (contiguous, vectorised, columns split among threads).
// Bounded grids hold the edges fixed (the outlets are base level); periodic
// grids solve the cyclic system by Sherman-Morrison.
#include <algorithm>
#include <vector>

#include "erosion/erosion.hpp"

namespace ft::erosion {
namespace {

// Thomas factors of (-r, 1 + 2r, -r) on a line of `len` samples; with
// `fixed_ends` the first and last rows are identity (Dirichlet).
struct LineSolver {
  std::vector<float> a, cp, inv;  // sub-diagonal, modified super-diagonal, 1 / pivot
  std::vector<float> z;           // cyclic only: the solution for the correction vector
  bool cyclic = false;
  float gamma = 0, beta = 0, alpha = 0, z_scale = 0;

  LineSolver(int32_t len, double r, bool fixed_ends) {
    std::vector<double> aa(len, -r), bb(len, 1 + 2 * r), cc(len, -r);
    cyclic = !fixed_ends;
    if (fixed_ends) {
      bb[0] = bb[len - 1] = 1;
      cc[0] = aa[len - 1] = 0;
    } else {
      // A = A' + u v^T with u = (gamma, 0.., alpha), v = (1, 0.., beta / gamma).
      alpha = float(-r);  // A[len-1][0]
      beta = float(-r);   // A[0][len-1]
      gamma = float(-bb[0]);
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
      inv[j] = float(1.0 / pivot);
      prev_cp = (j + 1 < len) ? cc[j] / pivot : 0.0;
      cp[j] = float(prev_cp);
    }
    if (cyclic) {
      z.assign(len, 0.0f);
      z[0] = gamma;
      z[len - 1] = alpha;
      solve_plain(z.data(), 1);
      z_scale = 1.0f + z[0] + beta * z[len - 1] / gamma;
    }
  }

  // In place on line[j * stride], j = 0..len-1.
  void solve_plain(float* line, size_t stride) const {
    const int32_t len = int32_t(cp.size());
    line[0] *= inv[0];
    for (int32_t j = 1; j < len; ++j) line[j * stride] = (line[j * stride] - a[j] * line[(j - 1) * stride]) * inv[j];
    for (int32_t j = len - 2; j >= 0; --j) line[j * stride] -= cp[j] * line[(j + 1) * stride];
  }
  void solve(float* line) const {
    solve_plain(line, 1);
    if (cyclic) correct(line, 1, 1);
  }
  // x = y - (v.y / (1 + v.z)) z on `count` adjacent lines.
  void correct(float* lines, size_t stride, size_t count) const {
    const int32_t len = int32_t(cp.size());
    for (size_t c = 0; c < count; ++c) {
      const float fact = (lines[c] + beta * lines[(len - 1) * stride + c] / gamma) / z_scale;
      for (int32_t j = 0; j < len; ++j) lines[j * stride + c] -= fact * z[j];
    }
  }
};

}  // namespace

void hillslope_diffusion(const D8Grid& g, float* z, double diffusivity_dt) {
  const double r = std::min(diffusivity_dt / (g.spacing * g.spacing), double(kMaxSolveFactor));
  const LineSolver along_x(g.width, r, !g.periodic), along_y(g.height, r, !g.periodic);
  const size_t w = size_t(g.width);
  // Rows: each is a contiguous line. Bounded: the first and last rows are
  // outlets and stay.
  const int32_t y0 = g.periodic ? 0 : 1, y1 = g.periodic ? g.height : g.height - 1;
#pragma omp parallel for schedule(static)
  for (int32_t y = y0; y < y1; ++y) along_x.solve(z + y * w);
  // Columns: the Thomas recurrences run over whole row segments. Bounded:
  // the first and last columns stay (save and restore them).
  std::vector<float> left(g.height), right(g.height);
  if (!g.periodic)
    for (int32_t y = 0; y < g.height; ++y) left[y] = z[y * w], right[y] = z[y * w + w - 1];
  const int32_t len = g.height;
  const int32_t block = 256;
  const int32_t blocks = int32_t((w + block - 1) / block);
#pragma omp parallel for schedule(static)
  for (int32_t b = 0; b < blocks; ++b) {
    const size_t x0 = size_t(b) * block, x1 = std::min(w, x0 + block);
    float* base = z + x0;
    const size_t cnt = x1 - x0;
    for (size_t c = 0; c < cnt; ++c) base[c] *= along_y.inv[0];
    for (int32_t j = 1; j < len; ++j) {
      float* row = base + j * w;
      const float* prev = row - w;
      const float aj = along_y.a[j], ij = along_y.inv[j];
      for (size_t c = 0; c < cnt; ++c) row[c] = (row[c] - aj * prev[c]) * ij;
    }
    for (int32_t j = len - 2; j >= 0; --j) {
      float* row = base + j * w;
      const float* next = row + w;
      const float cj = along_y.cp[j];
      for (size_t c = 0; c < cnt; ++c) row[c] -= cj * next[c];
    }
    if (along_y.cyclic) along_y.correct(base, w, cnt);
  }
  if (!g.periodic)
    for (int32_t y = 0; y < g.height; ++y) z[y * w] = left[y], z[y * w + w - 1] = right[y];
}

}  // namespace ft::erosion
