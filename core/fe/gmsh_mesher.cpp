#include "gmsh_mesher.hpp"

#include <dlfcn.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <stdexcept>
#include <string>

#include "errors.hpp"
#include "gmsh_tetrahedra.hpp"
#include "interrupt.hpp"

namespace dc::fe {

namespace {

/// Where the Gmsh plugin may be, in order: $DYNCONTACT_GMSH_PLUGIN; beside the program or
/// library that holds this code, as installed (bin/../lib/dyncontact); the build tree; the
/// configured install prefix.
std::vector<std::filesystem::path> gmsh_plugin_candidates() {
  std::vector<std::filesystem::path> paths;
  if (const char* env = std::getenv("DYNCONTACT_GMSH_PLUGIN"); env && *env) paths.emplace_back(env);
  Dl_info self{};
  if (dladdr(reinterpret_cast<void*>(&mesh_body), &self) && self.dli_fname)
    paths.push_back(std::filesystem::path(self.dli_fname).parent_path() / DYNCONTACT_GMSH_PLUGIN_FROM_BINDIR /
                    DYNCONTACT_GMSH_PLUGIN_NAME);
  paths.emplace_back(DYNCONTACT_GMSH_PLUGIN_BUILD);
  paths.emplace_back(DYNCONTACT_GMSH_PLUGIN_INSTALL);
  return paths;
}

/// The plugin's entry point, loaded once (Gmsh's start-up is paid by runs that mesh a body only).
GmshTetrahedraFunction gmsh_tetrahedra_function() {
  static const GmshTetrahedraFunction function = [] {
    std::string tried;
    for (const auto& path : gmsh_plugin_candidates()) {
      std::error_code ec;
      if (!std::filesystem::is_regular_file(path, ec)) {
        tried += "\n  " + path.string() + " (not found)";
        continue;
      }
      void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
      if (!handle) {
        tried += "\n  " + path.string() + " (" + dlerror() + ")";
        continue;
      }
      if (void* symbol = dlsym(handle, gmsh_tetrahedra_symbol))
        return reinterpret_cast<GmshTetrahedraFunction>(symbol);
      tried += "\n  " + path.string() + " (no entry point " + gmsh_tetrahedra_symbol + ")";
      dlclose(handle);
    }
    throw std::runtime_error("the Gmsh plugin " + std::string(DYNCONTACT_GMSH_PLUGIN_NAME) +
                             " could not be loaded (set DYNCONTACT_GMSH_PLUGIN to its path); tried:" + tried);
  }();
  return function;
}

void assign_regions(const FeBodySpec& spec, BodyMesh& mesh) {
  double z_min = std::numeric_limits<double>::infinity();
  for (const auto& x : mesh.nodes) z_min = std::min(z_min, x.z());
  for (std::size_t e = 0; e < mesh.elements.size(); ++e) {
    double zc = 0.0;
    for (int i = 0; i < 4; ++i) zc += 0.25 * mesh.nodes[mesh.elements[e][i]].z();
    mesh.region[e] = 0;
    for (std::size_t r = 0; r < spec.regions.size(); ++r)
      if (zc - z_min < spec.regions[r].z_below) {
        mesh.region[e] = static_cast<int>(r) + 1;
        break;
      }
  }
}

}  // namespace

BodyMesh mesh_body(const FeBodySpec& spec) {
  const std::string key = spec.shape == FeShape::mesh ? "fe_body.mesh" : "fe_body";
  if (spec.shape == FeShape::mesh && !std::filesystem::is_regular_file(spec.mesh_file))
    throw InputError("fe_body.mesh", "file '" + spec.mesh_file + "' not found");
  GmshTetrahedra gmsh;
  std::string error;
  bool meshed = false;
  {
    const NonPollingSection section("meshing the body (Gmsh)");
    meshed = gmsh_tetrahedra_function()(spec, gmsh, error);
  }
  if (!meshed) throw InputError(key, "Gmsh could not read or mesh the body: " + error);
  const auto& tets = gmsh.tets;
  if (tets.empty()) throw InputError(key, "the mesh has no tetrahedra (a volume mesh is needed)");
  BodyMesh mesh = quadratic_mesh_from_linear(gmsh.vertices, tets, key, gmsh.curved.empty() ? nullptr : &gmsh.curved);
  assign_regions(spec, mesh);
  return mesh;
}

}  // namespace dc::fe
