// SPDX-License-Identifier: GPL-3.0-or-later
// The measures of seed 003 for a polyline p1..pn, relative to its chord
// p1 -> pn (so a line on the unit horizontal segment gives the paper's
// numbers directly, and any other line is measured in units of its chord):
//   eta   = max_i |y_i|,  chi = mean_i |y_i|   (eq. 1a; y_i = distance of p_i
//           from the chord's line / |chord|, over all n vertices)
//   gamma = sum |p_i - p_{i+1}| / |p1 - pn|    (eq. 1b, the elongation)
// and the mass dimension of eq. 4g with an element ratio of 2 (as eq. 6):
//   D = 1 / (1 - log2(M_r / M_{r-1})),
// where M_r is the line's length and M_{r-1} the length through every second
// vertex, i.e. the line one recursion earlier for midpoint-refined lines
// (FPL, dragon, profile), whose nodes survive refinement.
#pragma once

#include <cmath>
#include <cstdint>
#include <string>

#include "analysis/box_counting.hpp"
#include "core/polyline_set.hpp"

namespace ft::analysis {

struct LineStats {
  double eta = NAN, chi = NAN, gamma = NAN;  // NaN for < 2 vertices or a zero chord
  double length = 0.0, chord = 0.0;
  int64_t vertices = 0;
};

LineStats line_stats(const PolylineSet& set, int64_t line);
// NaN when the line has fewer than 3 vertices or M_r / M_{r-1} >= 2.
double mass_dimension(const PolylineSet& set, int64_t line);

struct PolylineMeasures {
  LineStats main;             // line 0
  double total_length = 0.0;  // of all lines
  double mass_dimension = NAN;
  bool box_ok = false;        // false: box counting was not possible (box_error says why)
  std::string box_error;
  BoxCountResult box;
};

PolylineMeasures measure_polylines(const PolylineSet& set, const BoxCountOptions& box = {});

}  // namespace ft::analysis
