#pragma once
// The elastic energy the half-space (and an fe_body) stores at the end of a dynamic step
// (docs/wear_energy.md "Dynamic runs"; the step's frictional work is nlp's frictional_work).
// Used by ContactWrench::accept for the run's energy audit (dynamic_simulation.hpp).
#include <vector>

#include "linear_operator.hpp"

namespace dc::dynamics {

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
