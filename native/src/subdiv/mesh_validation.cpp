// SPDX-License-Identifier: GPL-3.0-or-later
#include "subdiv/mesh_validation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/error.hpp"

namespace ft::subdiv {
namespace {

std::string face_name(size_t f) { return "face " + std::to_string(f); }

uint64_t edge_key(uint32_t a, uint32_t b) { return (uint64_t(a) << 32) | b; }

void check_sharpness(const char* what, size_t i, float s) {
  if (!(s >= 0.0f && s <= 10.0f))
    invalid(std::string(what) + " " + std::to_string(i) + " has sharpness " + format_number(s) +
            "; allowed is [0, 10] (10 = infinitely sharp)");
}

}  // namespace

void validate_mesh(const Mesh& m) {
  if (m.positions.size() % 3 != 0)
    invalid("positions hold " + std::to_string(m.positions.size()) + " floats; need 3 per vertex (xyz)");
  const size_t nv = m.vertex_count();
  if (nv > size_t(std::numeric_limits<int32_t>::max()))
    fail(FT_ERR_TOO_LARGE, "the mesh has " + std::to_string(nv) + " vertices; at most 2^31 - 1 are allowed");
  for (size_t i = 0; i < m.positions.size(); ++i)
    if (!std::isfinite(m.positions[i]))
      invalid("vertex " + std::to_string(i / 3) + " has a non-finite coordinate (" +
              format_number(m.positions[i]) + ")");
  if (m.face_sizes.empty()) invalid("the mesh has no faces; give at least one polygon");

  // Sizes and the index count first, so the loops below stay in bounds.
  uint64_t total = 0;
  for (size_t f = 0; f < m.face_count(); ++f) {
    if (m.face_sizes[f] < 3)
      invalid(face_name(f) + " has " + std::to_string(m.face_sizes[f]) + " vertices; a face needs at least 3");
    total += uint64_t(m.face_sizes[f]);
  }
  if (total != m.face_indices.size())
    invalid("the face sizes add up to " + std::to_string(total) + " but " +
            std::to_string(m.face_indices.size()) + " face indices were given");
  if (total > uint64_t(std::numeric_limits<int32_t>::max()))
    fail(FT_ERR_TOO_LARGE, "the mesh has " + std::to_string(total) + " face corners; at most 2^31 - 1 are allowed");

  std::vector<uint64_t> directed;  // (from, to) per face edge, then the face
  directed.reserve(total);
  std::vector<int32_t> sorted;
  size_t first = 0;
  for (size_t f = 0; f < m.face_count(); ++f) {
    const int32_t n = m.face_sizes[f];
    const int32_t* idx = m.face_indices.data() + first;
    for (int32_t i = 0; i < n; ++i)
      if (idx[i] < 0 || size_t(idx[i]) >= nv)
        invalid(face_name(f) + " refers to vertex " + std::to_string(idx[i]) + "; vertex indices must be in 0.." +
                std::to_string(int64_t(nv) - 1));
    sorted.assign(idx, idx + n);
    std::sort(sorted.begin(), sorted.end());
    auto dup = std::adjacent_find(sorted.begin(), sorted.end());
    if (dup != sorted.end())
      invalid(face_name(f) + " uses vertex " + std::to_string(*dup) +
              " twice; a face needs distinct vertices (degenerate faces are not allowed)");
    for (int32_t i = 0; i < n; ++i) directed.push_back(edge_key(uint32_t(idx[i]), uint32_t(idx[(i + 1) % n])));
    const auto [nx, ny, nz] = face_vector_area(m, idx, n);
    if (nx == 0 && ny == 0 && nz == 0)
      invalid(face_name(f) + " has zero area (its vertices coincide or lie on a line); degenerate faces are not allowed");
    first += size_t(n);
  }

  // Each directed edge once: two faces walking an edge the same way are
  // either inconsistently oriented or two of >= 3 faces on one edge, which
  // OpenSubdiv tolerates as non-manifold but which has no outside to
  // displace along.
  std::vector<uint32_t> order(directed.size());
  for (uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
    return directed[a] != directed[b] ? directed[a] < directed[b] : a < b;
  });
  // corner -> face, for the messages
  auto face_of_corner = [&](uint32_t corner) {
    size_t f = 0, start = 0;
    while (start + size_t(m.face_sizes[f]) <= corner) start += size_t(m.face_sizes[f++]);
    return f;
  };
  for (size_t i = 1; i < order.size(); ++i)
    if (directed[order[i]] == directed[order[i - 1]]) {
      const uint64_t k = directed[order[i]];
      invalid("faces " + std::to_string(face_of_corner(order[i - 1])) + " and " +
              std::to_string(face_of_corner(order[i])) + " both run along the edge from vertex " +
              std::to_string(k >> 32) + " to vertex " + std::to_string(k & 0xffffffffu) +
              " in the same direction; faces must be oriented consistently and at most two faces may share "
              "an edge (" + face_name(face_of_corner(order[i])) + " is the offending face)");
    }

  if (m.crease_pairs.size() != 2 * m.crease_sharpness.size())
    invalid("creases need 2 vertex indices and 1 sharpness each; got " + std::to_string(m.crease_pairs.size()) +
            " indices for " + std::to_string(m.crease_sharpness.size()) + " sharpness values");
  std::sort(directed.begin(), directed.end());
  for (size_t c = 0; c < m.crease_sharpness.size(); ++c) {
    const int32_t a = m.crease_pairs[2 * c], b = m.crease_pairs[2 * c + 1];
    check_sharpness("crease", c, m.crease_sharpness[c]);
    const bool in_range = a >= 0 && b >= 0 && size_t(a) < nv && size_t(b) < nv;
    if (!in_range || (!std::binary_search(directed.begin(), directed.end(), edge_key(uint32_t(a), uint32_t(b))) &&
                      !std::binary_search(directed.begin(), directed.end(), edge_key(uint32_t(b), uint32_t(a)))))
      invalid("crease " + std::to_string(c) + " names vertices " + std::to_string(a) + " and " + std::to_string(b) +
              ", which are not the ends of an edge of the mesh");
  }
  if (m.corner_vertices.size() != m.corner_sharpness.size())
    invalid("corners need one vertex and one sharpness each; got " + std::to_string(m.corner_vertices.size()) +
            " vertices and " + std::to_string(m.corner_sharpness.size()) + " sharpness values");
  for (size_t c = 0; c < m.corner_vertices.size(); ++c) {
    if (m.corner_vertices[c] < 0 || size_t(m.corner_vertices[c]) >= nv)
      invalid("corner " + std::to_string(c) + " names vertex " + std::to_string(m.corner_vertices[c]) +
              "; vertex indices must be in 0.." + std::to_string(int64_t(nv) - 1));
    check_sharpness("corner", c, m.corner_sharpness[c]);
  }
}

void validate_triangles(const Mesh& m) {
  for (size_t f = 0; f < m.face_count(); ++f)
    if (m.face_sizes[f] != 3)
      invalid(face_name(f) + " has " + std::to_string(m.face_sizes[f]) +
              " vertices; Loop subdivision needs triangles only (use catmark or bilinear, or triangulate)");
}

}  // namespace ft::subdiv
