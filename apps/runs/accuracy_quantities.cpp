#include "accuracy_quantities.hpp"

#include <cmath>

namespace dc::runs {
namespace {

double number(const nlohmann::json& s, const char* key) {
  return s.contains(key) && s[key].is_number() ? s[key].get<double>() : 0.0;
}

/// The rim pressure ratio from which the pressure is taken to peak at the rim: a Hertzian edge gives
/// sqrt(2 h / a) <= 0.6 with the 6 elements across the contact an estimate needs at least.
constexpr double kRimPeak = 0.9;

bool is_pair(const nlohmann::json& s, const char* key) {
  return s.contains(key) && s[key].is_array() && s[key].size() == 2;
}

}  // namespace

std::vector<QuantityValue> accuracy_quantities(const nlohmann::json& s) {
  using C = Convergence;
  std::vector<QuantityValue> q;
  const double force = std::abs(number(s, "normal_force"));
  const double pressure = number(s, "max_pressure");
  // The control fixes one of force and approach; the other is the answer (approach under force
  // control converges at O(h^2) overall but not from grid to grid: docs/accuracy.md).
  const bool force_control = s.value("control", std::string("force")) == "force";
  // Where the pressure peaks at the contact's rim (a punch, a sharp profile edge, small patches)
  // the force and the approach converge by whole elements at first order, not at O(h^2), and
  // Richardson's number falls below their error (the flat punch: docs/accuracy.md): a band.
  const bool rim_peak = number(s, "contact_rim_pressure_ratio") >= kRimPeak;
  const C global = rim_peak ? C::band : C::smooth;
  if (force_control)
    q.push_back({"approach", number(s, "approach"), global, 0.0});
  else
    q.push_back({"normal_force", force, global, 0.0});
  q.push_back({"max_pressure", pressure, rim_peak ? C::rim_peak : C::peak, 0.0});
  // An element is in the contact or not: the area moves by whole elements, not monotonically.
  q.push_back({"contact_area", number(s, "contact_area"), C::band, 0.0, true});
  if (s.contains("contact_half_width")) q.push_back({"contact_half_width", number(s, "contact_half_width"), C::band, 0.0, true});
  if (!is_pair(s, "tangential_force")) return q;

  // The tangential results depend on where the contact edge and the stick-slip boundary fall
  // within an element: from grid to grid they change by up to 10 x their error (Carter's
  // creepage, Mindlin's shift: docs/accuracy.md), so Richardson's number falls below the true
  // error in one case of four. They get the band of the changes, which holds in 19 of 20.
  const double fx = s["tangential_force"][0].get<double>(), fy = s["tangential_force"][1].get<double>();
  const double capacity = number(s, "friction_capacity");
  const double tiny = 1e-6 * capacity;  // a force component that is zero in the continuum
  q.push_back({"tangential_force", std::hypot(fx, fy), C::band, tiny});
  q.push_back({"Fx", fx, C::band, tiny});
  q.push_back({"Fy", fy, C::band, tiny});
  const double mz = number(s, "twisting_moment");
  const double length = std::sqrt(std::max(number(s, "contact_area"), 0.0));
  q.push_back({"twisting_moment", mz, C::band, tiny * length});
  q.push_back({"Mz", mz, C::band, tiny * length});
  // A shift that is zero in the continuum (Spence's symmetric indentation): its scale is the
  // shift of gross sliding, about mu times the approach (Cattaneo: 3 mu P (2 - nu) / (16 G a)).
  const double friction = force > 0.0 ? capacity / force : 0.0;
  if (is_pair(s, "rigid_shift"))
    q.push_back({"rigid_shift", std::hypot(s["rigid_shift"][0].get<double>(), s["rigid_shift"][1].get<double>()),
                 C::band, 1e-6 * friction * std::abs(number(s, "approach"))});
  if (is_pair(s, "creepage"))
    q.push_back({"creepage", std::hypot(s["creepage"][0].get<double>(), s["creepage"][1].get<double>()), C::band, 0.0});
  const double area = number(s, "contact_area");
  q.push_back({"stick_area", number(s, "stick_area"), C::band, 1e-6 * area, true});
  q.push_back({"slip_area", number(s, "slip_area"), C::band, 1e-6 * area, true});
  if (area > 0.0) q.push_back({"stick_fraction", number(s, "stick_area") / area, C::band, 1e-6});
  return q;
}

}  // namespace dc::runs
