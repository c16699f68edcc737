// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/quantile.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <vector>

#include "core/error.hpp"
#include "core/memory.hpp"

namespace ft::analysis {

LevelSpec parse_level(const std::string& text, const char* what) {
  LevelSpec s;
  std::string t = text;
  if (!t.empty() && (t[0] == 'q' || t[0] == 'Q')) s.quantile = true, t = t.substr(1);
  char* end = nullptr;
  s.value = t.empty() ? NAN : std::strtod(t.c_str(), &end);
  if (t.empty() || end != t.c_str() + t.size() || !std::isfinite(s.value))
    invalid(std::string(what) + " '" + text + "' is neither a height (e.g. 0.25) nor a quantile (e.g. q0.5)");
  if (s.quantile) check_range(what, s.value, 0.0, 1.0);
  return s;
}

double heightfield_quantile(const Heightfield& hf, double q) {
  check_range("quantile", q, 0.0, 1.0);
  if (hf.size() == 0) invalid("the quantile of an empty heightfield is undefined");
  check_allocation(checked_bytes(hf.size(), sizeof(float)), "a sorted copy of the heightfield");
  std::vector<float> v(hf.data(), hf.data() + hf.size());
  for (size_t i = 0; i < v.size(); ++i)
    if (std::isnan(v[i])) invalid("heightfield sample " + std::to_string(i) + " is NaN; quantiles need numbers");
  const double pos = q * double(v.size() - 1);
  const size_t k = size_t(std::floor(pos));
  std::nth_element(v.begin(), v.begin() + ptrdiff_t(k), v.end());
  const double lo = v[k];
  if (k + 1 >= v.size() || pos == double(k)) return lo;
  const double hi = *std::min_element(v.begin() + ptrdiff_t(k) + 1, v.end());
  return lo + (pos - double(k)) * (hi - lo);
}

double resolve_level(const Heightfield& hf, const LevelSpec& spec) {
  if (spec.quantile) return heightfield_quantile(hf, spec.value);
  check_finite("level", spec.value);
  return spec.value;
}

}  // namespace ft::analysis
