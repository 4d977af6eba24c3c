#pragma once
// fields.vti (CASES.md "Files"): the surface fields of a state as VTK image data that ParaView
// opens, one point per element centre (2-D: a row of points along x, y = 0), the contact plane
// z = 0. Point arrays: pressure (Pa), traction (tx, ty, 0; Pa, on the body as in fields.csv), slip
// (sx, sy, 0; m), state (0 free, 1 stick, 2 slip), and when the state has them friction_bound
// (Pa), dissipation (J/m^2) or power (W/m^2) as fields.csv names its column, temperature_base
// and temperature_body (K), and the extra maps a run adds (each worn body's depth, m). A history's
// steps and a dynamic run's snapshots: fields_<k>.vti in the series fields.pvd.
#include <string>
#include <utility>
#include <vector>

#include "grid.hpp"
#include "pvd_collection.hpp"
#include "static_fields.hpp"

namespace dc::output {

/// A per-element map written beside the fields (e.g. {"wear_base", &depth}); empty maps are left out.
using NamedMap = std::pair<std::string, const std::vector<double>*>;

/// Writes dir/`file` whole; returns the file's name.
std::string write_fields_vti(const std::string& dir, const Grid& grid, const StaticFields& fields,
                             const std::string& file = "fields.vti", const std::vector<NamedMap>& extra = {});

/// The surface fields of a run in time as a ParaView series: fields_<k>.vti per state and
/// fields.pvd, rewritten with each (time values: the dynamic run's times, a history's steps).
class FieldsSnapshots {
 public:
  explicit FieldsSnapshots(std::string dir) : dir_(std::move(dir)) {}
  /// Writes fields_<step>.vti and rewrites fields.pvd; returns the image's name.
  std::string write(const Grid& grid, const StaticFields& fields, int step, double time,
                    const std::vector<NamedMap>& extra = {});
  std::size_t count() const { return files_.size(); }
  std::string collection() const { return "fields.pvd"; }

 private:
  std::string dir_;
  std::vector<PvdEntry> files_;
};

}  // namespace dc::output
