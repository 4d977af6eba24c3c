// Gmsh is a plugin loaded when a body is first meshed: a process that never meshes a body does
// not map it (its start-up, about 0.2 s of OpenCASCADE and FLTK, was paid by every run while it
// was linked in), and meshing loads it and works.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "fe_body_spec.hpp"
#include "elastic_stiffness.hpp"
#include "gmsh_mesher.hpp"

namespace dc {
namespace {

bool gmsh_is_mapped() {
  std::ifstream maps("/proc/self/maps");
  std::string line;
  while (std::getline(maps, line))
    if (line.find("libgmsh") != std::string::npos) return true;
  return false;
}

TEST(GmshPlugin, LoadedOnlyWhenABodyIsMeshed) {
  EXPECT_FALSE(gmsh_is_mapped()) << "Gmsh is linked into the program again: every run pays its start-up";
  FeBodySpec block;
  block.shape = FeShape::block;
  block.size = {1.0, 1.0, 0.5};
  block.elements = {2, 2, 1};
  block.material = {fe::isotropic_stiffness(2.1e11, 0.3, "test"), 7800.0};
  const fe::BodyMesh mesh = fe::mesh_body(block);
  EXPECT_TRUE(gmsh_is_mapped());
  EXPECT_GT(mesh.elements.size(), 0u);
  double z_min = 1e9, z_max = -1e9;
  for (const auto& x : mesh.nodes) {
    z_min = std::min(z_min, x.z());
    z_max = std::max(z_max, x.z());
  }
  EXPECT_NEAR(z_max - z_min, 0.5, 1e-12);  // the block's height, from the plugin's geometry
}

}  // namespace
}  // namespace dc
