#pragma once
// A ParaView collection (.pvd): the files of a series with their time values, which ParaView
// opens as one time-dependent dataset (the body's body_NNNN.vtu, the subsurface's
// subsurface_NNNN.vti).
#include <string>
#include <vector>

namespace dc::output {

struct PvdEntry {
  double time = 0.0;  ///< the series' time value (s; a history's step number)
  std::string file;   ///< relative to the collection's folder
};

/// Writes `path` whole (output_files.hpp) listing `entries` in order.
void write_pvd(const std::string& path, const std::vector<PvdEntry>& entries);

}  // namespace dc::output
