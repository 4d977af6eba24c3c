#pragma once
// The subsurface field's files (CASES.md): subsurface.vti, VTK image data that ParaView opens
// (x, y as the grid's element centres, the third axis the depth into each body, positive; per
// body <name>_stress (Voigt xx, yy, zz, yz, xz, xy, Pa), <name>_von_mises, <name>_tresca and
// <name>_displacement), written when the depths are evenly spaced; and the planes through each
// body's worst point, subsurface_<name>_xz.csv (3-D also _yz.csv):
// x (or y), depth, sxx, syy, szz, syz, sxz, sxy, von_mises, tresca. Runs in time: a series of
// subsurface_<step>.vti in subsurface.pvd.
#include <string>
#include <vector>

#include "pvd_collection.hpp"
#include "subsurface_field.hpp"

namespace dc::output {

struct SubsurfaceBody {
  std::string name;
  const SubsurfaceResult* field = nullptr;
  const SubsurfaceMeasures* measures = nullptr;
};

/// Whether `depths` are evenly spaced (an image's third axis); a single depth counts.
bool evenly_spaced(const std::vector<double>& depths);

/// Writes dir/`name` (default subsurface.vti) whole; returns the name. Needs evenly spaced depths.
std::string write_subsurface_vti(const std::string& dir, const std::vector<SubsurfaceBody>& bodies,
                                 const std::string& name = "subsurface.vti");

/// The field of a run in time as a ParaView series: subsurface_<step>.vti per state and
/// subsurface.pvd, rewritten with each (its time values: the dynamic run's times, a history's steps).
class SubsurfaceSnapshots {
 public:
  explicit SubsurfaceSnapshots(std::string dir) : dir_(std::move(dir)) {}
  /// Writes subsurface_<step>.vti and rewrites subsurface.pvd; returns the image's name.
  std::string write(const std::vector<SubsurfaceBody>& bodies, int step, double time);
  std::size_t count() const { return files_.size(); }
  std::string collection() const { return "subsurface.pvd"; }

 private:
  std::string dir_;
  std::vector<PvdEntry> files_;
};

/// Writes the planes through each body's largest von Mises stress; returns their names.
std::vector<std::string> write_subsurface_planes(const std::string& dir, const std::vector<SubsurfaceBody>& bodies);

}  // namespace dc::output
