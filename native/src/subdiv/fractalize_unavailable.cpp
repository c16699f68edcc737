// SPDX-License-Identifier: GPL-3.0-or-later
// Stands in for fractalize.cpp in a build without OpenSubdiv
// (FT_WITH_OPENSUBDIV=OFF: the Windows build): the mesh and parameters are
// checked as usual, then the call refuses, naming the library.
#include "core/build_features.hpp"
#include "subdiv/fractalize.hpp"
#include "subdiv/mesh_validation.hpp"

namespace ft::subdiv {

Mesh fractalize(const Mesh& mesh, const ft_fractalize_params&) {
  validate_mesh(mesh);
  needs("fractalize (subdivision of a mesh)", "OpenSubdiv");
}

}  // namespace ft::subdiv
