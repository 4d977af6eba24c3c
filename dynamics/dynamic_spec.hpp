#pragma once
// The blocks of a "dynamic" case (CASES.md): the massive body (mass, inertia, initial motion),
// the external loads (value + rate t per component), the time stepping and the contact models.
// Read by the case layer (apps/case/read_dynamic.cpp); the stepper and the contact wrench take
// DynamicSpec and never see JSON. DynamicContactSpec: what a dynamic run takes.
#include <array>
#include <optional>

#include "contact_spec.hpp"

namespace dc {

/// value + rate * t of one load component.
struct ValueRate {
  double value = 0.0, rate = 0.0;
};

/// How the normal contact follows the body: `dynamic` - the approach from the body's height
/// (3-D); `quasi_static` - the normal force from the vertical balance (the body's height does
/// not move; always so in 2-D, where plane strain fixes the approach only up to a reference).
enum class NormalModel { dynamic, quasi_static };
/// The tangential traction of a step: `transient` - (3.8), the previous traction carried over
/// the step's travel; `steady` - the steady-rolling solution at the step's creepage and spin;
/// `automatic` - transient when the travel V dt is below a quarter of the contact half-length.
enum class ContactModel { transient, steady, automatic };

struct DynamicSpec {
  double mass = 0.0;                        ///< body.mass (kg; 2-D kg/m)
  std::array<double, 3> inertia{};          ///< body.inertia: principal moments about x, y, z (kg m^2; 2-D per m)
  double radius = 0.0;                      ///< body.radius: height of the centre of mass over the lowest point (m)
  std::array<double, 3> position{}, velocity{}, omega{};  ///< body.initial
  bool has_position = false;                ///< else the body starts touching: z = radius
  std::array<ValueRate, 3> force{}, moment{};  ///< loads.force.{x,y,z}, loads.moment.{x,y,z}
  double dt = 0.0, t_end = 0.0;             ///< time (s)
  bool bdf2 = false;                        ///< time.scheme
  /// time.adaptive: error-controlled steps (docs/dynamics.md "Adaptive time steps"); `dt` is then
  /// the first step. rtol, atol: the local error's tolerances (atol a speed, m/s: a position's
  /// error is weighed per unit step, the angular parts times the gyration radius); dt_min,
  /// dt_max: the step's bounds (s).
  bool adaptive = false;
  double rtol = 1e-4, atol = 1e-9, dt_min = 0.0, dt_max = 0.0;
  /// time.energy_tolerance: the largest energy imbalance of an accepted run (balances.energy;
  /// above it the run is known wrong: a limit error naming time.dt).
  double energy_tolerance = 0.05;
  /// time.allow_coarse_dt: accept fewer than kMinStepsPerContact steps per Hertz contact time.
  bool allow_coarse_dt = false;
  NormalModel normal_model = NormalModel::dynamic;
  ContactModel contact_model = ContactModel::automatic;
  /// An fe_body (docs/dynamics.md "A finite-element body"): mass, inertia and radius come from
  /// its mesh and density; given ones (has_*) are checked against the mesh's. Shift and torsion
  /// only (2.16): no rolling, no convected or steady contact model.
  bool fe_body = false;
  bool has_mass = false, has_inertia = false, has_radius = false;
};

/// The contact (nlp/contact_spec.hpp) and the massive body's motion: what DynamicSimulation,
/// ContactWrench and the dynamic limits take (the case layer's Case is one).
struct DynamicContactSpec : ContactSpec {
  std::optional<DynamicSpec> dynamic;  ///< problem dynamic
};

const char* to_string(NormalModel model);
const char* to_string(ContactModel model);

}  // namespace dc
