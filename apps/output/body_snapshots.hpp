#pragma once
// The finite-element body of a dynamic run as a ParaView series: body_NNNN.vtu per snapshot
// (vtu_writer.hpp: displacement, stress, von Mises; the mesh placed at the body's position)
// and body.pvd, the collection ParaView opens with its time values.
#ifdef DYNCONTACT_WITH_FE
#include <string>
#include <vector>

#include "finite_body.hpp"
#include "pvd_collection.hpp"
#include "rigid_body.hpp"

namespace dc::output {

class BodySnapshots {
 public:
  explicit BodySnapshots(std::string dir) : dir_(std::move(dir)) {}
  /// Writes the next body_NNNN.vtu at `state` and rewrites body.pvd; returns the file name.
  std::string write(const dynamics::FiniteBody& body, const dynamics::RigidBodyState& state);
  std::size_t count() const { return files_.size(); }
  /// "body.pvd"
  std::string collection() const { return "body.pvd"; }

 private:
  std::string dir_;
  std::vector<PvdEntry> files_;
};

}  // namespace dc::output
#endif
