// SPDX-License-Identifier: GPL-3.0-or-later
// Network measures (see network_measures.hpp).
#include "hydrology/network_measures.hpp"

#include <algorithm>
#include <map>

#include "analysis/loglog_fit.hpp"
#include "core/error.hpp"

namespace ft::hydrology {

NetworkMeasures measure_network(const RiverNetwork& net) {
  NetworkMeasures m;
  const auto& segs = net.segments;
  m.segments = int64_t(segs.size());
  m.lakes = int64_t(net.water.lakes.size());
  m.vertices = net.lines.vertex_count();
  m.total_length = net.total_length;
  const double cell = net.grid.spacing * net.grid.spacing;
  for (const int32_t l : net.water.label) m.land_area += l == kLand ? cell : 0.0;
  m.drainage_density = m.land_area > 0 ? m.total_length / m.land_area : 0.0;
  // Streams: segments grouped by their stream id.
  std::map<int32_t, analysis::NetworkStream> streams;
  for (const Segment& s : segs) {
    analysis::NetworkStream& st = streams[s.stream];
    st.order = s.order;
    st.length += s.length;
    ++m.ends[int(s.end)];
  }
  std::vector<analysis::NetworkStream> list;
  for (const auto& [id, st] : streams) list.push_back(st);
  int32_t top = 0;
  for (const auto& st : list) top = std::max(top, st.order);
  if (top >= 2) {
    m.horton = analysis::horton_ratios(list);
    m.has_horton = true;
  }
  // Hack: the longest path from a channel head to each segment's mouth
  // against the drainage area there (segments come upstream first; a lake
  // passes on its longest inflow).
  std::vector<double> end_length(segs.size(), 0.0), start_length(segs.size(), 0.0);
  std::vector<double> lake_length(net.water.lakes.size(), 0.0);
  std::vector<double> a, l;
  for (size_t s = 0; s < segs.size(); ++s) {
    const Segment& seg = segs[s];
    if (seg.from_lake >= 0) start_length[s] = std::max(start_length[s], lake_length[size_t(seg.from_lake)]);
    end_length[s] = start_length[s] + seg.length;
    if (seg.downstream >= 0)
      start_length[size_t(seg.downstream)] = std::max(start_length[size_t(seg.downstream)], end_length[s]);
    if (seg.lake >= 0) lake_length[size_t(seg.lake)] = std::max(lake_length[size_t(seg.lake)], end_length[s]);
    a.push_back(net.area[size_t(seg.first_vertex + seg.vertex_count - 1)]);
    l.push_back(end_length[s]);
  }
  if (a.size() >= 3) {
    const analysis::LogLogFit f = analysis::fit_loglog(a, l, "Hack's law");
    m.hack_h = f.slope, m.hack_h_stderr = f.slope_stderr, m.hack_points = f.points;
  }
  return m;
}

}  // namespace ft::hydrology
