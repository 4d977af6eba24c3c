#pragma once
// The interface between the Gmsh plugin (libdyncontact_gmsh, gmsh_plugin/gmsh_plugin.cpp) and
// the program that loads it on first use (gmsh_mesher.cpp): what the plugin hands back.
#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "fe_body_spec.hpp"

namespace dc::fe {

/// A body as Gmsh meshed or read it: vertices, linear tetrahedra (corner indices) and, when
/// every tetrahedron has them, the six curved mid-edge points of each (second-order mesh).
struct GmshTetrahedra {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int, 4>> tets;
  std::vector<std::array<Eigen::Vector3d, 6>> curved;
};

/// The plugin's entry point, exported as `gmsh_tetrahedra_symbol` (C linkage): false with
/// Gmsh's message in `error` when Gmsh cannot build or read the body.
using GmshTetrahedraFunction = bool (*)(const FeBodySpec& spec, GmshTetrahedra& out, std::string& error);
inline constexpr const char* gmsh_tetrahedra_symbol = "dyncontact_gmsh_tetrahedra";

}  // namespace dc::fe
