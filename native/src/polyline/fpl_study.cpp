// SPDX-License-Identifier: GPL-3.0-or-later
#include "polyline/fpl_study.hpp"

#include <cmath>

#include "analysis/box_counting.hpp"
#include "analysis/polyline_stats.hpp"
#include "core/error.hpp"

namespace ft::polyline {
namespace {

MeanSe mean_se(const std::vector<double>& v) {
  MeanSe r;
  double sum = 0, n = 0;
  for (double x : v)
    if (std::isfinite(x)) sum += x, ++n;
  if (n == 0) return {NAN, NAN};
  r.mean = sum / n;
  double ss = 0;
  for (double x : v)
    if (std::isfinite(x)) ss += (x - r.mean) * (x - r.mean);
  r.se = n > 1 ? std::sqrt(ss / (n - 1) / n) : NAN;
  return r;
}

}  // namespace

PaperFit paper_fit(FplRng rng) {
  return rng == FplRng::kUniform ? PaperFit{0.65, 0.29, 0.71, 1.82} : PaperFit{1.23, 0.5, 1.34, 1.58};
}

std::vector<FplStudyRow> run_fpl_study(const FplStudyConfig& c) {
  if (c.spreads.empty() || c.depths.empty()) invalid("the study needs at least one spread and one depth");
  for (double s : c.spreads)
    if (!(s >= 0) || !std::isfinite(s)) invalid("every spread must be a finite number >= 0, got " + format_number(s));
  for (int r : c.depths) check_int_range("depth", r, 1, 20);
  check_int_range("count", c.count, 2, 100000);
  const PaperFit fit = paper_fit(c.rng);
  std::vector<FplStudyRow> rows;
  const size_t total = c.spreads.size() * c.depths.size();
  for (double s : c.spreads)
    for (int r : c.depths) {
      std::vector<double> eta(size_t(c.count)), chi(eta), gamma(eta), mass(eta), box(eta);
      const int64_t n = (int64_t(1) << r) + 1;
#pragma omp parallel for schedule(dynamic, 4)
      for (int k = 0; k < c.count; ++k) {
        FplConfig f;
        f.rng = c.rng;
        f.spread = s;
        f.depth = r;
        f.seed = c.seed + uint64_t(k);
        PolylineSet line;
        line.points.resize(size_t(n));
        line.radii.assign(size_t(n), 0.0);
        fpl_segment(f, {0, 0, 0}, {1, 0, 0}, 0, line.points.data());
        line.end_line();
        const analysis::LineStats st = analysis::line_stats(line, 0);
        eta[size_t(k)] = st.eta;
        chi[size_t(k)] = st.chi;
        gamma[size_t(k)] = st.gamma;
        mass[size_t(k)] = analysis::mass_dimension(line, 0);
        box[size_t(k)] = NAN;
        if (c.box_counting && r >= 6 && s > 0) {
          try {
            box[size_t(k)] = analysis::box_counting_dimension(line).dimension;
          } catch (const Error&) {
          }
        }
      }
      FplStudyRow row;
      row.spread = s;
      row.depth = r;
      row.count = c.count;
      row.eta = mean_se(eta);
      row.chi = mean_se(chi);
      row.gamma = mean_se(gamma);
      row.mass_dimension = mean_se(mass);
      row.box_dimension = mean_se(box);
      const double a = fit.alpha * std::pow(s, fit.beta);
      row.paper_eta = fit.eta_per_s * s;
      row.paper_chi = fit.chi_per_s * s;
      row.paper_gamma = std::exp2(a * r);
      row.paper_dimension = a < 1 ? 1.0 / (1.0 - a) : NAN;
      rows.push_back(row);
      c.progress.report(double(rows.size()) / double(total));
    }
  return rows;
}

}  // namespace ft::polyline
