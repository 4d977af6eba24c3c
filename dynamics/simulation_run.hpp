#pragma once
// What a run of DynamicSimulation carries from step to step (dynamic_simulation.cpp, the fixed
// steps; adaptive_steps.cpp, time.adaptive): its result and limits, the sums of its balances,
// the output callback. Internal to the two.
#include <functional>

#include "dynamic_limits.hpp"
#include "dynamic_simulation.hpp"

namespace dc::dynamics {

struct DynamicSimulation::Run {
  explicit Run(const DynamicContactSpec& c, const std::function<void(const DynamicSample&)>& f)
      : on_step(f), limits(c) {}
  const std::function<void(const DynamicSample&)>& on_step;
  DynamicResult result;
  DynamicLimitTracker limits;
  RigidBodyState state;
  Eigen::Vector3d impulse = Eigen::Vector3d::Zero();
  double impulse_size = 0.0, external_work = 0.0, contact_work = 0.0;
  double initial_kinetic = 0.0, initial_elastic = 0.0, dissipated = 0.0, largest_elastic = 0.0;
  Wrench contact_at_step_start;  // the last accepted step's contact wrench (before the first: t = 0's)
};

}  // namespace dc::dynamics
