// SPDX-License-Identifier: GPL-3.0-or-later
// Checks a mesh before it reaches OpenSubdiv, so bad input gets a message
// that names the offending face, edge or vertex instead of a crash or an
// OpenSubdiv warning on stdout.
#pragma once

#include "core/mesh.hpp"

namespace ft::subdiv {

// Throws FT_ERR_INVALID_ARGUMENT unless: positions are finite and a multiple
// of 3; there is at least one face; every face has >= 3 distinct vertex
// indices in range and non-zero area; the index count is the sum of the face
// sizes; each directed edge belongs to at most one face (faces oriented
// consistently, at most two faces per edge); creases name existing edges and
// corners existing vertices, with sharpness in [0, 10].
void validate_mesh(const Mesh& mesh);

// Additionally for Loop subdivision: every face is a triangle.
void validate_triangles(const Mesh& mesh);

}  // namespace ft::subdiv
