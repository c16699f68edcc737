// SPDX-License-Identifier: GPL-3.0-or-later
// The cube-sphere layout (fracterra/planet.h documents the face convention):
// six faces of (2^n + 1)^2 samples, sample (i, j) of face f standing for the
// integer cube point N n_f + (2i - N) s_f + (2j - N) t_f (N = 2^n). A sample
// shared by two or three faces is the same integer point on each, and its
// unit vector is computed from that point alone (integer sums of squares are
// exact in double up to level 26), so shared samples are equal bit for bit.
#pragma once

#include <array>
#include <cstdint>

#include "core/heightfield.hpp"
#include "core/mesh.hpp"
#include "planet/planet.hpp"

namespace ft::planet {

inline constexpr int kMaxLevel = 26;
inline constexpr int kMaxMeshLevel = 12;

struct CubePoint {
  int64_t x, y, z;
  bool operator==(const CubePoint&) const = default;
};

// Sample (i, j) of face `face` (0..5: +X, -X, +Y, -Y, +Z, -Z) at N = 2^level.
CubePoint cube_point(int face, int64_t i, int64_t j, int64_t n);
// Its direction, normalised in double.
std::array<double, 3> unit_vector(const CubePoint& p);
// (i, j) of `p` on face `face` if it lies on that face, else false.
bool face_sample(const CubePoint& p, int face, int64_t n, int64_t* i, int64_t* j);
// The outward normal of face `face` (a unit axis).
std::array<int, 3> face_normal(int face);
// The point d n_f + s s_f + t t_f of face `face`'s frame (normal, column and
// row directions): cube_point(face, i, j, n) is face_point(face, n, 2i - n, 2j - n).
CubePoint face_point(int face, int64_t d, int64_t s, int64_t t);
// Sample (i, j) of face `face`'s plane at N = n, one coordinate allowed up to
// n past the face: the plane folded over that edge onto the next face (the
// cube net), so (-1, j) is the sample of the next face one row in from the
// shared edge. Inside the face it is cube_point().
CubePoint folded_point(int face, int64_t i, int64_t j, int64_t n);
// The first face (0..5) holding `p` at N = n, and its (i, j) there.
int locate(const CubePoint& p, int64_t n, int64_t* i, int64_t* j);
// The face a direction lies on (its largest component's axis and sign) and
// its continuous face coordinates (s, t) in [-1, 1] (gnomonic).
int face_of_direction(double x, double y, double z, double* s, double* t);

// Validates level, face and the patch (inside the face's samples).
void validate_patch(int level, int face, int64_t x0, int64_t y0, int64_t w, int64_t h);
// The samples (x0 .. x0 + w - 1, y0 .. y0 + h - 1) of face `face` at `level`.
Heightfield face_patch(const Planet& planet, int level, int face, int64_t x0, int64_t y0, int32_t w, int32_t h);

// Throws unless the mesh exaggeration is finite and within +-1e6.
void check_vertical_scale(double vertical_scale);
// An fBm planet's heights at u, in parallel rows (progress, cancel).
std::vector<float> heights_in_rows(const Planet& planet, const Directions& u, const Progress& progress);
// Mesh positions into xyz (3 per direction): each direction times radius +
// vertical_scale x its height, in parallel rows (progress, cancel).
void place_on_sphere(const Directions& u, const std::vector<float>& h, double radius, double vertical_scale,
                     int threads, const Progress& progress, float* xyz);

// Vertex and quad counts of the closed mesh: 6 N^2 + 2 and 6 N^2.
int64_t mesh_vertex_count(int level);
int64_t mesh_face_count(int level);

// Where the closed mesh goes: 3 floats per vertex, 4 vertex ids per quad, 1
// height per vertex (metres above the radius); each may be null (not made).
struct MeshArrays {
  float* xyz = nullptr;
  int32_t* corners = nullptr;
  float* heights = nullptr;
};
// The closed cube-sphere mesh into `out`: every sample once, at radius +
// scale x height along its direction; quads counter-clockwise seen from
// outside. Checks its working memory plus `output_bytes` (the arrays', when
// the library holds them) against the cap; reports progress (the planet's)
// throughout and stops at a cancel; the same bits on any thread count.
void cube_sphere_arrays(const Planet& planet, int level, double vertical_scale, const MeshArrays& out,
                        uint64_t output_bytes = 0);
// The same as a Mesh; `heights` (if not null) gets each vertex's height.
Mesh cube_sphere_mesh(const Planet& planet, int level, double vertical_scale, std::vector<float>* heights = nullptr);

}  // namespace ft::planet
