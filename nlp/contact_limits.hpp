#pragma once
// Results the program knows to be wrong or outside its model, found from the contact's size:
// a contact truncated by the grid's edge, a contact too coarse to resolve (by the grid, or by an
// fe_body's face elements), and a contact as large as the body's radius of curvature (linear
// elasticity and the half-space void). One set of rules for every run kind and entry point: the
// command line's summary.json "limits", the Python module, the dynamic runs (dynamic_limits.hpp).
#include <string>
#include <vector>

#include "contact_spec.hpp"

namespace dc {

struct ResultLimit {
  std::string key;      ///< the case key that accepts it or must change (grid, materials)
  std::string message;
  bool error = false;   ///< a wrong result not accepted by the case: exit 2
  bool accepted = false;  ///< known wrong, and accepted by a key of the case (allow_*)
};

/// The contact's size as measured (after a solve) or estimated (Hertz, for validate).
struct ContactSize {
  double half_width_x = 0.0, half_width_y = 0.0;  ///< m (2-D: y unused)
  double edge_fraction = 0.0;   ///< of the grid's edge elements in contact (estimates: 0 or 1)
  int across_x = -1, across_y = -1;  ///< elements across the contact (-1: not known)
  double face_element_size = 0.0;    ///< an fe_body's face elements over the contact (m; 0: none)
};

std::vector<ResultLimit> result_limits(const ContactSpec& c, const ContactSize& size);

}  // namespace dc
