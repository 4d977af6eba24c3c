#pragma once
// The energy of a dynamic step's contact (docs/wear_energy.md "Dynamic runs"): the frictional
// work dissipated over the step and the elastic energy the half-space (and an fe_body) stores
// at its end. Used by ContactWrench::accept for the run's energy audit (dynamic_simulation.hpp).
#include <vector>

#include "linear_operator.hpp"
#include "tangential_problem.hpp"

namespace dc::dynamics {

/// -sum_e tau_e . ds_e A: the work the traction on the body does against the slip of the step
/// (2.4)-(2.5), >= 0 by the friction law (J; 2-D J/m). `slip_per_step`: ds per the solution's
/// slip (1 for a transient step, whose sx, sy are the step's; V_x dt / dx for a steady-rolling
/// solution, whose slip is per dx of travel).
double frictional_work(const TangentialSolution& s, double area, double slip_per_step);

/// elastic_energy's scratch vectors, kept by the caller (a dynamic step allocates nothing).
struct EnergyScratch {
  std::vector<double> tau, displacement, coupled;
};

/// The elastic energy of the contact, 1/2 sum p u_n A + 1/2 sum tau . u_t A (J; 2-D J/m): the
/// normal part from the closed gap, u_n = approach - h_e where p > 0 (`heights` the undeformed
/// gap (2.6); none when `pressure` is null or `with_normal` is false), the tangential part
/// u_t = B22 tau + kappa B21 p from the compliances (`coupling` null when kappa = 0; no traction:
/// none). tx, ty per element, ty empty or zero in 2-D.
double elastic_energy(const std::vector<double>* pressure, const std::vector<double>& heights, double approach,
                      bool with_normal, const std::vector<double>& tx, const std::vector<double>& ty,
                      const LinearOperator* tangential_compliance, const LinearOperator* coupling, double area,
                      EnergyScratch& scratch);

}  // namespace dc::dynamics
