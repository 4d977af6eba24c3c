#pragma once
// The result limits of a "dynamic" run (docs/limits.md): what is known wrong before the run
// (a time step too coarse for the Hertz contact time of an impact or of a body released from
// inside the half-space, an estimated contact the grid or the half-space model cannot hold) and what the run shows
// at any step (the contact reaching the grid's edge, a/R, a body penetrating between the grid's
// elements, too few steps in a contact, the energy balance).
#include <optional>
#include <vector>

#include "dynamic_spec.hpp"
#include "contact_limits.hpp"
#include "dynamic_simulation.hpp"

namespace dc::dynamics {

/// Fewer steps than this in a Hertz contact time and the impact's peak force and rebound are
/// off by several per cent (ball-impact, bdf2: 14 steps 8 %, 7 steps 19 %, 2 steps 70 %).
inline constexpr double kMinStepsPerContact = 20.0;

/// The Hertz estimate of a dynamic case's largest contact (3-D curved profiles; the sizing load
/// of grid.extent). In the dynamic normal model the body moves vertically in V(d) = U(d) - P d
/// under the static load P (U the Hertz energy, Johnson 11.4; V = -P d above the surface): its
/// deepest approach sizes the contact (an impact's peak force; 2.5 P for a load applied at once
/// to a body resting on the surface), and it is released, as the impact of its energy at first
/// touch (kinetic + V(d0)), only when that energy is positive.
struct DynamicContactEstimate {
  double load = 0.0;            ///< N
  double approach = 0.0;        ///< m, at that load
  double half_width_x = 0.0, half_width_y = 0.0;  ///< m
  double contact_time = 0.0;    ///< s, of an impact (2.94 delta_max / v0); 0: no impact
  double steps_per_contact = 0.0;  ///< contact_time / dt (0: no impact)
  double start_inside = 0.0;    ///< m, how far the body starts inside the half-space (0: outside)
};

/// The normal load that sizes a dynamic case's `grid.extent` when it has no `normal` block: the
/// static vertical load P (-loads.force.z) or, in 3-D on a curved profile, the force at the
/// deepest approach of the vertical motion (dynamic normal model) or of a Hertz impact at the
/// initial downward speed (quasi-static normal model), whichever is larger; false when none is
/// positive.
bool dynamic_sizing_load(const DynamicSpec& spec, const ContactSpec& c, NormalSpec& load);

/// None for a case without a Hertz estimate (2-D, flat or table profiles, an fe_body).
std::optional<DynamicContactEstimate> estimate_dynamic_contact(const DynamicContactSpec& c);

/// Before anything is solved: throws InputError naming time.dt (an impact, or the release of a
/// body pressed in, with fewer than kMinStepsPerContact steps in its contact time, unless
/// time.allow_coarse_dt or time.adaptive) or the key of an error limit of the estimated contact
/// (grid: the contact beyond the grid; materials: a/R); returns the warnings.
std::vector<ResultLimit> dynamic_limits_before(const DynamicContactSpec& c);

/// Follows a run step by step; limits() after it.
class DynamicLimitTracker {
 public:
  explicit DynamicLimitTracker(const DynamicContactSpec& c);
  void add(const DynamicSample& s);
  /// The limits of the run so far (grid edge at any step, a/R and resolution at the largest
  /// contact, penetration no element saw, short contacts, the energy balance of `r`).
  std::vector<ResultLimit> limits(const DynamicResult& r) const;

 private:
  const DynamicContactSpec& case_;
  double reference_approach_ = 0.0;  ///< the Hertz estimate's, 0 without one
  ContactSize largest_{};            ///< at the step with the most elements in contact
  int largest_n_ = 0;
  double worst_edge_fraction_ = 0.0;
  double worst_edge_time_ = 0.0;
  double unseen_approach_ = 0.0;     ///< largest approach of a step with no element in contact
  double unseen_time_ = 0.0;
  double seen_approach_ = 0.0;       ///< largest approach of a step in contact
  int episode_steps_ = 0;            ///< steps of the current contact
  int shortest_episode_ = 0;         ///< of the finished contacts (0: none finished)
  double shortest_episode_time_ = 0.0;
};

}  // namespace dc::dynamics
