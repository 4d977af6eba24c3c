#include "fe_body_estimate.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "errors.hpp"

namespace dc::runs {
namespace {

// Calibration on Gmsh meshes of the finite-hemisphere example (R = 10 mm, grid +-0.9 mm: contact
// elements 0.11 mm over a 0.9 mm disk) at elements [8,8,4], [16,16,8], [24,24,12]: 2660, 7031 and
// 18759 tetrahedra (the estimate within 2 %), 14.2k, 34.7k and 86.6k dofs, peak memory 133, 299
// and 881 MB, 2.2, 7.1 and 24 s.
constexpr double kTetsPerRefinedVolume = 6.6;  // tetrahedra per h(x)^3 of volume in the refined zone
constexpr double kTetsPerCoarseVolume = 4.7;   // ... and at the coarse size
constexpr double kDofsPerTet = 4.4, kDofsBase = 2500.0;
constexpr double kMemoryBase = 5.6e7, kMemoryPerDof43 = 215.0;  // bytes: base + c n^(4/3) (3-D factor)
constexpr double kSecondsPerDof17 = 1.5e-7;                     // s: c n^1.7

double body_volume(const FeBodySpec& s) {
  switch (s.shape) {
    case FeShape::block: return s.size[0] * s.size[1] * s.size[2];
    case FeShape::cylinder: return std::numbers::pi * s.radius * s.radius * s.height;
    case FeShape::hemisphere: return 2.0 / 3.0 * std::numbers::pi * s.radius * s.radius * s.radius;
    case FeShape::mesh: break;
  }
  return 0.0;
}

std::string format_bytes(double b) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.3g GB", b / 1e9);
  return buf;
}

}  // namespace

std::optional<FeBodyEstimate> estimate_fe_body(const Case& c) {
  if (!c.fe_body || c.fe_body->shape == FeShape::mesh) return std::nullopt;
  FeBodySpec s = *c.fe_body;  // the sizes FiniteContact gives the mesher (finite_contact.cpp)
  const double r0 = s.refine_radius.value_or(grid_refine_radius(c.grid));
  if (s.contact_size == 0.0) s.default_contact_size_bound = default_contact_size_bound(s, c.materials.base, c.grid);
  const double h = fe_coarse_size(s), h0 = fe_contact_element_size(s), volume = body_volume(s);
  if (!(h > 0.0 && h0 > 0.0 && volume > 0.0)) return std::nullopt;
  // The refined zone: points at distance d from the disk r <= r0 of the lowest point, inside the
  // body (a half-space near the contact): area pi r0^2 + pi^2 r0 d + 2 pi d^2 at distance d, where
  // the size is h0 + g d, up to d = (h - h0) / g.
  const double g = kFaceSizeGrowth, reach = std::max(0.0, (h - h0) / g);
  const int pieces = 2000;
  double refined = 0.0, refined_volume = 0.0;
  for (int i = 0; i < pieces; ++i) {
    const double d = (i + 0.5) / pieces * reach, dd = reach / pieces;
    const double area = std::numbers::pi * (r0 * r0 + std::numbers::pi * r0 * d + 2.0 * d * d);
    refined += area * dd / std::pow(h0 + g * d, 3);
    refined_volume += area * dd;
  }
  refined_volume = std::min(refined_volume, volume);
  const double coarse = (volume - refined_volume) / (h * h * h);
  FeBodyEstimate e;
  e.tetrahedra = kTetsPerRefinedVolume * refined + kTetsPerCoarseVolume * coarse;
  e.refined_share = kTetsPerRefinedVolume * refined / e.tetrahedra;
  e.dofs = kDofsPerTet * e.tetrahedra + kDofsBase;
  e.memory_bytes = kMemoryBase + kMemoryPerDof43 * std::pow(e.dofs, 4.0 / 3.0);
  e.seconds = kSecondsPerDof17 * std::pow(e.dofs, 1.7);
  e.key = e.refined_share > 0.5 ? "fe_body.contact_size" : "fe_body.elements";
  return e;
}

void check_fe_body_fits(const Case& c) {
  const auto e = estimate_fe_body(c);
  if (!e) return;
  const double available = available_memory_bytes();
  if (e->memory_bytes <= available) return;
  char what[256];
  std::snprintf(what, sizeof what, "about %.3g tetrahedra and %.3g dofs", e->tetrahedra, e->dofs);
  throw InputError(e->key, std::string("the body's mesh (") + what + ") needs about " +
                               format_bytes(e->memory_bytes) + " to factorise, more than the " +
                               format_bytes(available) + " this machine has available; " +
                               (e->key == "fe_body.contact_size"
                                    ? "a larger fe_body.contact_size (the elements at the contact)"
                                    : "fewer fe_body.elements (the coarse divisions)") +
                               " or a smaller grid (its reach sets the refined disk)");
}

}  // namespace dc::runs
