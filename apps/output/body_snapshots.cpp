#ifdef DYNCONTACT_WITH_FE
#include "body_snapshots.hpp"

#include <cstdio>
#include <filesystem>
#include <sstream>

#include "elastic_body.hpp"
#include "output_files.hpp"
#include "vtu_writer.hpp"

namespace dc::output {

std::string BodySnapshots::write(const dynamics::FiniteBody& body, const dynamics::RigidBodyState& state) {
  const fe::ElasticBody& elastic = body.elastic_body();
  // The mesh where the body is: x = R + q (X - centre of mass).
  fe::BodyMesh placed = elastic.mesh();
  for (auto& x : placed.nodes) x = state.position + state.orientation * (x - elastic.centre_of_mass());
  char name[32];
  std::snprintf(name, sizeof name, "body_%04zu.vtu", files_.size());
  const std::filesystem::path folder(dir_);
  write_body_vtu((folder / name).string(), placed, body.displacement(), elastic.element_stress(body.displacement()));
  files_.emplace_back(state.time, name);
  const std::string pvd = (folder / collection()).string();
  std::ostringstream out;
  out.precision(12);
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      << "<Collection>\n";
  for (const auto& [t, file] : files_) out << "<DataSet timestep=\"" << t << "\" group=\"\" part=\"0\" file=\"" << file << "\"/>\n";
  out << "</Collection>\n</VTKFile>\n";
  write_file_whole(pvd, out.str());
  return name;
}

}  // namespace dc::output
#endif
