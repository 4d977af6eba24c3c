#pragma once
// The "subsurface" block of a static run (CASES.md): the elastic field inside each named body
// from the final state's tractions (core/subsurface_field.hpp, by FFT per depth), its von Mises,
// Tresca (tau_1) and orthogonal-shear (|sigma_xz|) maxima with their places for summary.json,
// and the field for subsurface.vti and the planes' CSV (output/subsurface_writer.hpp).
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "case_model.hpp"
#include "static_fields.hpp"
#include "subsurface_field.hpp"
#include "subsurface_writer.hpp"

namespace dc::runs {

/// One body's field and its measures.
struct BodySubsurface {
  std::string name;  ///< "base" or "body"
  SubsurfaceResult field;
  SubsurfaceMeasures measures;
  FieldExtreme max_orthogonal_shear;  ///< |sigma_xz|
};

struct SubsurfaceRun {
  std::vector<double> depths;
  std::vector<BodySubsurface> bodies;  ///< the named, elastic ones
  std::vector<std::string> rigid;      ///< named but rigid: no field
};

/// `c` with c.subsurface.bodies holding every body a yield, fatigue or shakedown verdict needs
/// besides those the block names.
Case with_verdict_bodies(const Case& c);

/// The depths of `spec`, or 32 from 0 to 1.5 x `half_width` (the contact's larger half-width).
std::vector<double> subsurface_depths(const SubsurfaceSpec& spec, double half_width);
/// The same with the half-width of `summary` (contact_half_width, or the larger of _x and _y).
std::vector<double> subsurface_depths(const SubsurfaceSpec& spec, const nlohmann::json& summary);

/// The field of every named body of `c` (on `grid`, the grid solved) under `fields`' tractions
/// at `depths`.
SubsurfaceRun compute_subsurface(const Case& c, const Grid& grid, const output::StaticFields& fields,
                                 const std::vector<double>& depths);
/// The same at subsurface_depths(c.subsurface, summary).
SubsurfaceRun compute_subsurface(const Case& c, const Grid& grid, const output::StaticFields& fields,
                                 const nlohmann::json& summary);

/// The bodies of `run` as the writers take them (output/subsurface_writer.hpp).
std::vector<output::SubsurfaceBody> subsurface_bodies(const SubsurfaceRun& run);

/// summary.json's "subsurface": per body max_von_mises, at, max_tresca, at_tresca,
/// max_orthogonal_shear, at_orthogonal ([x, y, depth]; 2-D [x, depth]), and the depths.
nlohmann::json subsurface_json(const SubsurfaceRun& run, int dimension);

/// The block's files in `dir` (output/subsurface_writer.hpp) when the case asks for the field:
/// subsurface.vti (evenly spaced depths) and, with `planes`, the planes through each body's worst
/// point; their names into `files` ("subsurface", "subsurface_planes"), as summary.json lists them.
/// Returns the bodies written (subsurface_bodies; none without the block).
std::vector<output::SubsurfaceBody> write_subsurface_files(const std::string& dir, const Case& c,
                                                          const SubsurfaceRun& run, nlohmann::json& files);

/// The maxima per body on stdout (the solve command's report).
void print_subsurface(const SubsurfaceRun& run);

}  // namespace dc::runs
