// SPDX-License-Identifier: GPL-3.0-or-later
#include "planet/sphere_spectrum.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "analysis/loglog_fit.hpp"
#include "core/error.hpp"
#include "core/memory.hpp"
#include "core/parallel.hpp"
#include "planet/cube_sampler.hpp"

namespace ft::planet {

namespace {

// Gauss-Legendre nodes (cos theta, descending) and weights of n points.
void gauss_legendre(int n, std::vector<double>* x, std::vector<double>* w) {
  // Newton's method on P_n from Tricomi's estimate of each root.
  x->assign(size_t(n), 0.0);
  w->assign(size_t(n), 0.0);
  for (int i = 0; i < (n + 1) / 2; ++i) {
    double z = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5)), dp = 1;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1, p1 = z;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1) * z * p1 - (k - 1.0) * p0) / k;
        p0 = p1, p1 = p2;
      }
      const double pn = n == 1 ? z : p1, pm = n == 1 ? 1.0 : p0;
      dp = n * (z * pn - pm) / (z * z - 1.0);
      const double dz = pn / dp;
      z -= dz;
      if (std::fabs(dz) < 1e-16) break;
    }
    (*x)[size_t(i)] = z, (*x)[size_t(n - 1 - i)] = -z;
    (*w)[size_t(i)] = (*w)[size_t(n - 1 - i)] = 2.0 / ((1.0 - z * z) * dp * dp);
  }
}

}  // namespace

ShGrid::ShGrid(int lmax_) : lmax(lmax_), nlat(4 * (lmax_ + 1)), nlon(8 * (lmax_ + 1)) {
  check_int_range("lmax", lmax, 2, kMaxSpectrumDegree);
  gauss_legendre(nlat, &x, &w);
}

std::array<double, 3> ShGrid::direction(int k, int j) const {
  const double s = std::sqrt(std::max(0.0, 1.0 - x[size_t(k)] * x[size_t(k)]));
  const double phi = 2.0 * std::numbers::pi * j / nlon;
  return {s * std::cos(phi), s * std::sin(phi), x[size_t(k)]};
}

std::vector<double> angular_power_spectrum(const Planet& planet, int lmax) {
  check_int_range("lmax", lmax, 2, kMaxSpectrumDegree);
  const ShGrid grid(lmax);
  const int nlat = grid.nlat, nlon = grid.nlon;
  check_allocation(checked_bytes(uint64_t(nlat), uint64_t(nlon), 4) +
                       checked_bytes(uint64_t(nlat) + uint64_t(nlon), uint64_t(lmax + 1), 16),
                   "the grid of a degree-" + std::to_string(lmax) + " spectrum");
  std::vector<float> h(size_t(nlat) * size_t(nlon));
  const ProgressPart part(planet.config().progress, 0.0, 0.7);
  if (planet.midpoint()) {
    const CubeSampler sampler(planet.midpoint_config(), sampler_level_for(std::numbers::pi / nlat),
                              planet.config().threads, part.progress());
    for (int k = 0; k < nlat; ++k)
      for (int j = 0; j < nlon; ++j) {
        const auto p = grid.direction(k, j);
        h[size_t(k) * nlon + size_t(j)] = sampler.height(p[0], p[1], p[2]);
      }
    planet.raise_to_sea(int64_t(h.size()), h.data());
  } else {
    fill_rows(nlon, nlat, planet.config().threads, part.progress(),
              [&](int32_t k, float* row) {
                Directions d{size_t(nlon)};
                for (int j = 0; j < nlon; ++j) d.set(size_t(j), grid.direction(k, j));
                planet.heights(d, row);
              },
              h.data());
  }
  std::vector<double> power = power_spectrum(grid, h.data(), planet.config().threads);
  planet.config().progress.report(1.0);
  return power;
}

std::vector<double> power_spectrum(const ShGrid& grid, const float* h, int threads) {
  const int nlat = grid.nlat, nlon = grid.nlon, nm = grid.lmax + 1, lmax = grid.lmax;
  const std::vector<double>& x = grid.x;
  const std::vector<double>& w = grid.w;
  // F_km = (2 pi / nlon) sum_j h_kj e^(-i m phi_j), m = 0..lmax.
  std::vector<double> c(size_t(nlon) * nm), s(size_t(nlon) * nm);
  for (int j = 0; j < nlon; ++j)
    for (int m = 0; m < nm; ++m) {
      const double a = 2.0 * std::numbers::pi * double((int64_t(j) * m) % nlon) / nlon;
      c[size_t(j) * nm + size_t(m)] = std::cos(a), s[size_t(j) * nm + size_t(m)] = std::sin(a);
    }
  std::vector<double> re(size_t(nlat) * nm, 0.0), im(size_t(nlat) * nm, 0.0);
  const int team = resolve_threads(threads);
#pragma omp parallel for num_threads(team) schedule(static)
  for (int k = 0; k < nlat; ++k) {
    double* r = re.data() + size_t(k) * nm;
    double* q = im.data() + size_t(k) * nm;
    for (int j = 0; j < nlon; ++j) {
      const double v = h[size_t(k) * nlon + size_t(j)] * (2.0 * std::numbers::pi / nlon);
      const double* cj = c.data() + size_t(j) * nm;
      const double* sj = s.data() + size_t(j) * nm;
      for (int m = 0; m < nm; ++m) r[m] += v * cj[m], q[m] -= v * sj[m];
    }
  }
  // a_lm = sum_k w_k lambda_lm(x_k) F_km; lambda_lm = N_lm P_l^m, orthonormal on the sphere with e^(i m phi).
  std::vector<double> power(size_t(nm), 0.0);
  std::vector<double> are(size_t(nm) * nm, 0.0), aim(size_t(nm) * nm, 0.0);  // [m][l]
#pragma omp parallel for num_threads(team) schedule(dynamic, 1)
  for (int m = 0; m < nm; ++m) {
    double* ar = are.data() + size_t(m) * nm;
    double* ai = aim.data() + size_t(m) * nm;
    // sqrt((2m + 1) / (4 pi) prod_{k <= m} (2k - 1) / (2k)), in logs.
    double log_mm = 0.5 * std::log((2.0 * m + 1) / (4.0 * std::numbers::pi));
    for (int k = 1; k <= m; ++k) log_mm += 0.5 * std::log((2.0 * k - 1) / (2.0 * k));
    for (int k = 0; k < nlat; ++k) {
      const double xk = x[size_t(k)], sk = std::sqrt(std::max(0.0, 1.0 - xk * xk));
      const double fr = re[size_t(k) * nm + size_t(m)] * w[size_t(k)], fi = im[size_t(k) * nm + size_t(m)] * w[size_t(k)];
      double p2 = 0, p1 = m == 0 ? std::exp(log_mm) : (sk > 0 ? std::exp(log_mm + m * std::log(sk)) : 0.0);
      ar[m] += p1 * fr, ai[m] += p1 * fi;
      for (int l = m + 1; l <= lmax; ++l) {
        const double a = std::sqrt((4.0 * l * l - 1.0) / (double(l) * l - double(m) * m));
        const double b = l == m + 1 ? 0.0
                                    : std::sqrt((double(l - 1) * (l - 1) - double(m) * m) / (4.0 * double(l - 1) * (l - 1) - 1.0));
        const double p = a * (xk * p1 - b * p2);
        p2 = p1, p1 = p;
        ar[l] += p * fr, ai[l] += p * fi;
      }
    }
  }
  for (int l = 0; l <= lmax; ++l) {
    double sum = 0;
    for (int m = 0; m <= l; ++m) {
      const double v = are[size_t(m) * nm + size_t(l)] * are[size_t(m) * nm + size_t(l)] +
                       aim[size_t(m) * nm + size_t(l)] * aim[size_t(m) * nm + size_t(l)];
      sum += m == 0 ? v : 2.0 * v;  // a_l,-m = (-1)^m conj(a_lm) for real heights
    }
    power[size_t(l)] = sum / (2.0 * l + 1.0);
  }
  return power;
}

SpectrumHurst spectrum_hurst(const std::vector<double>& power, int l_min, int l_max) {
  check_int_range("l_min", l_min, 1, int(power.size()) - 2);
  check_int_range("l_max", l_max, l_min + 1, int(power.size()) - 1);
  std::vector<double> l, c;
  for (int k = l_min; k <= l_max; ++k) l.push_back(k), c.push_back(power[size_t(k)]);
  const analysis::LogLogFit fit = analysis::fit_loglog(l, c, "the spherical-harmonic Hurst estimate");
  SpectrumHurst r;
  r.slope = fit.slope;
  r.hurst = (-fit.slope - 2.0) / 2.0;
  r.std_error = fit.slope_stderr / 2.0;
  r.l_min = l_min, r.l_max = l_max;
  return r;
}

}  // namespace ft::planet
