#pragma once
// What every contact solve takes, typed and without JSON or file names: the bodies' materials
// and profile, the grid, the normal load, the friction law, an optional finite-element body and
// the solver's options. The case layer (apps/case/case_model.hpp) reads a case file into one;
// dynamics/ extends it by the body's motion (DynamicContactSpec, dynamic_spec.hpp).
#include <optional>

#include "fe_body_spec.hpp"
#include "friction_law.hpp"
#include "grid.hpp"
#include "material.hpp"
#include "normal_spec.hpp"
#include "profile.hpp"
#include "solver_options.hpp"

namespace dc {

struct ContactSpec {
  int dimension = 3;  ///< 3, or 2: plane strain over strips
  MaterialPair materials;
  ProfileSpec profile;
  Grid grid;
  bool allow_edge_contact = false;  ///< grid.allow_edge_contact: a contact truncated by the grid edge is accepted
  bool allow_large_strain = false;  ///< materials.allow_large_strain: a contact as large as the body is accepted
  NormalSpec normal;
  std::optional<FrictionSpec> friction;
  std::optional<FeBodySpec> fe_body;  ///< problem finite, or a dynamic body of finite elements
  SolverOptions solver;               ///< the `solver` block (solver_options.hpp)
};

}  // namespace dc
