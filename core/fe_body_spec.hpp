#pragma once
// The finite-element body (CASES.md "fe_body"): shape or mesh file, mesh sizes, materials per
// region (nonhomogeneous), density. Read by the case layer (apps/case/read_fe_body.cpp); core/fe
// meshes it, nlp/finite and dynamics/finite solve with it.
#include <algorithm>
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "elastic_stiffness.hpp"
#include "grid.hpp"
#include "material.hpp"

namespace dc {

enum class FeShape { block, cylinder, hemisphere, mesh };

/// Elements whose centroid lies below `z_below` (measured from the body's lowest point) take
/// this material instead of the body's.
struct FeRegionSpec {
  double z_below = 0.0;
  fe::BodyMaterial material;
};

struct FeBodySpec {
  FeShape shape = FeShape::hemisphere;
  std::array<double, 3> size{0.0, 0.0, 0.0};  ///< block: lx, ly, height
  double radius = 0.0;                        ///< cylinder, hemisphere
  double height = 0.0;                        ///< cylinder
  std::string mesh_file;                      ///< shape mesh: a Gmsh file (tetrahedra)
  std::array<int, 3> elements{8, 8, 8};       ///< divisions of the extent: the coarse element size
  double contact_size = 0.0;                  ///< element size at the contact (0: the default below)
  /// Not given `contact_size`: the face's elements at the contact are coarse / 4, and at most this
  /// (0: no bound). FiniteContact sets it from the grid (`grid_contact_size`).
  double default_contact_size_bound = 0.0;
  /// Radius (m) of the disk about the body's lowest point (the contact face's centre, the grid's
  /// origin) over which the face's elements keep `contact_size`; beyond it they grow with the
  /// distance from that disk. Not given: the grid's reach (`grid_refine_radius`, taken by
  /// FiniteContact); 0 refines the lowest point alone.
  std::optional<double> refine_radius;
  fe::BodyMaterial material;
  std::vector<FeRegionSpec> regions;
  /// The program of the normal and tangential problems: "condensed" (the compliances C_hs +
  /// B'K+B / A, every backend) or "sparse" (the saddle form over the tractions and u with the
  /// equilibrium as sparse rows, Ipopt).
  std::string program = "condensed";
  /// The body's tilt: given rotations about x and y (rad, about the grid origin), or free with
  /// the moment rows of the rigid motion when `load_line` gives where the normal force's line of
  /// action crosses the plane (x, y in m; docs/finite.md). Neither: the mean rotation is held.
  std::array<double, 2> tilt{0.0, 0.0};
  std::optional<std::array<double, 2>> load_line;
};

/// The radius of the largest disk about the grid's origin inside the grid (0 when the origin lies
/// outside it): where the contact can lie, so where the body's face must resolve it.
double grid_refine_radius(const Grid& grid);

/// The default element size at the contact: an eighth of `grid_refine_radius` (two cells of a
/// 32 x 32 grid about the origin), 0 when the origin lies outside the grid. The grid spans the
/// contact with a margin, so this resolves the contact's radius a with some six elements:
/// measured on Hertz hemispheres (docs/finite.md, "Choosing contact_size"), p0 within 1 % and
/// the pressure within 3 % (L2), where the coarse / 4 of a large body gave 6-8.5 % and 16 %.
double grid_contact_size(const Grid& grid);

/// The body's normal compliance (1 - nu^2) / E against the half-space's: the largest over the
/// body's material and its regions, each taken isotropic by the Voigt averages of its stiffness
/// (bulk and shear moduli). 0 when the half-space is rigid.
double body_compliance_ratio(const FeBodySpec& body, const Elastic& halfspace);

/// The element size at the contact that a body more compliant than the half-space needs against
/// the grid's cells (+infinity when the body is the stiffer): 4 / sqrt(ratio) cells, at least
/// half a cell. Within a face element the pressure's grid-scale modes are resisted by the
/// half-space alone; a body `ratio` times as compliant leaves them nearly free, and the normal
/// problem ill-conditioned. Measured on Hertz hemispheres (32² over +-1.3-1.6 a): aluminium on
/// steel (ratio 3) at 2 cells p0 +1.3 %, L2 5.1 %, at 1.5 cells 0.6 %, 3.6 %; ratio 30 at 2
/// cells the native solver did not converge (p0 +230 %), at 1 cell p0 +0.7 %, L2 5.3 %; rubber on
/// steel (ratio 2e4) at 1 cell not converged, at 0.5 cells p0 +1.1 %, L2 3.8 %.
double face_cell_bound(const FeBodySpec& body, const Elastic& halfspace, const Grid& grid);

/// The bound on the default contact_size (FeBodySpec::default_contact_size_bound): the smaller of
/// `grid_contact_size` (when the grid holds the origin) and `face_cell_bound`; 0 when neither
/// applies (coarse / 4 alone).
double default_contact_size_bound(const FeBodySpec& body, const Elastic& halfspace, const Grid& grid);

/// The face's elements over the contact resolve it when their mean edge is at most this share of
/// the contact's half-width (Hertz hemispheres, pressure in L2: 3 % at 0.17, 7 % at 0.37, 16 % at
/// 1; docs/finite.md, "Choosing contact_size"): beyond it a run warns, or remeshes when the
/// case leaves contact_size to the default.
constexpr double kFaceResolvedShare = 1.0 / 3.0;
/// The contact_size of that remesh, as a share of the measured half-width.
constexpr double kRemeshShare = 1.0 / 6.0;

/// The extent of a generated shape (x, y, z; the mesh shape: zeros).
inline std::array<double, 3> fe_body_extent(const FeBodySpec& s) {
  switch (s.shape) {
    case FeShape::block: return s.size;
    case FeShape::cylinder: return {2.0 * s.radius, 2.0 * s.radius, s.height};
    case FeShape::hemisphere: return {2.0 * s.radius, 2.0 * s.radius, s.radius};
    case FeShape::mesh: break;
  }
  return {0.0, 0.0, 0.0};
}

/// The coarse element size: the extent over `elements`, the smallest of the three.
inline double fe_coarse_size(const FeBodySpec& s) {
  const std::array<double, 3> extent = fe_body_extent(s);
  double h = extent[0] / std::max(1, s.elements[0]);
  for (int i = 1; i < 3; ++i) h = std::min(h, extent[i] / std::max(1, s.elements[i]));
  return h;
}

/// The element size at the contact: contact_size (at most the coarse size), else a quarter of the
/// coarse size bounded by default_contact_size_bound.
inline double fe_contact_element_size(const FeBodySpec& s) {
  const double h = fe_coarse_size(s);
  if (s.contact_size > 0.0) return std::min(s.contact_size, h);
  return s.default_contact_size_bound > 0.0 ? std::min(0.25 * h, s.default_contact_size_bound) : 0.25 * h;
}

/// Growth of the element size per unit distance from the refined disk, up to the coarse size.
/// Measured on a steel hemisphere under a shift (R / a = 54, tractions against Cattaneo-Mindlin,
/// L2): the lowest point alone refined at a growth of 0.3 gave 27 % (11k dofs) and 15 % at 4 x the
/// elements (27k dofs; the contact's edge kept 0.3 a); the grid's disk at 0.6 gives 15 % with 12k
/// dofs and 8 % with 20k.
constexpr double kFaceSizeGrowth = 0.6;

}  // namespace dc
