// SPDX-License-Identifier: GPL-3.0-or-later
// The transect-median estimator: every row and every column of a surface is
// estimated as a profile, and the median H is reported. The median shrugs off
// the few transects that cross a cliff or a flat (clipped) region, which pull
// a pooled variogram; its spread gives the standard error.
#include <algorithm>
#include <cmath>

#include "analysis/hurst.hpp"
#include "core/error.hpp"

namespace ft::analysis::detail {

HurstEstimate transect_median(const Heightfield& hf, const HurstOptions& o) {
  const int64_t w = hf.width(), h = hf.height();
  const int64_t count = w + h;  // rows first, then columns
  std::vector<HurstEstimate> est(static_cast<size_t>(count));
  std::vector<char> ok(static_cast<size_t>(count), 0);
  // Bands are checked once up front so that a bad band is an error, not a
  // silently empty median.
  resolve_band(o, size_t(w));
  resolve_band(o, size_t(h));
#pragma omp parallel for schedule(dynamic, 4)
  for (int64_t t = 0; t < count; ++t) {
    try {
      est[size_t(t)] = t < h ? estimate_transect(hf.data() + t * w, size_t(w), 1, o)
                             : estimate_transect(hf.data() + (t - h), size_t(h), w, o);
      ok[size_t(t)] = std::isfinite(est[size_t(t)].hurst);
    } catch (const Error&) {
      // a constant transect (e.g. clipped sea level) has no estimate: skip it
    }
  }
  std::vector<std::pair<double, int64_t>> hs;
  for (int64_t t = 0; t < count; ++t)
    if (ok[size_t(t)]) hs.emplace_back(est[size_t(t)].hurst, t);
  if (hs.empty()) invalid("no row or column of the heightfield gives a Hurst estimate (is it constant?)");
  std::sort(hs.begin(), hs.end());
  const size_t m = hs.size();
  // The median's own transect carries the plotted points and band; for an
  // even count, H is the mean of the two middle values.
  HurstEstimate e = est[size_t(hs[m / 2].second)];
  e.hurst = m % 2 ? hs[m / 2].first : 0.5 * (hs[m / 2 - 1].first + hs[m / 2].first);
  double mean = 0, ss = 0;
  for (auto& p : hs) mean += p.first;
  mean /= double(m);
  for (auto& p : hs) ss += (p.first - mean) * (p.first - mean);
  // Standard error of a median: sqrt(pi / 2) sd / sqrt(m) for a normal spread.
  e.std_error = m > 1 ? std::sqrt(M_PI / 2) * std::sqrt(ss / double(m - 1)) / std::sqrt(double(m)) : 0.0;
  e.transects = true;
  e.transect_count = int(m);
  e.topological_dim = 2;
  e.dimension = 3 - e.hurst;
  return e;
}

}  // namespace ft::analysis::detail
