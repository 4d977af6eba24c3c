#ifdef DYNCONTACT_WITH_FE
#include "body_snapshots.hpp"

#include <cstdio>
#include <filesystem>

#include "elastic_body.hpp"
#include "output_files.hpp"
#include "pvd_collection.hpp"
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
  files_.push_back({state.time, name});
  write_pvd((folder / collection()).string(), files_);
  return name;
}

}  // namespace dc::output
#endif
