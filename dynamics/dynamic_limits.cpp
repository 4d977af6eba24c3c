#include "dynamic_limits.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "errors.hpp"
#include "hertz.hpp"

namespace dc::dynamics {
namespace {

std::string format(const char* f, double a, double b = 0.0, double c = 0.0) {
  char buf[512];
  std::snprintf(buf, sizeof buf, f, a, b, c);
  return buf;
}

/// The pressure field of a step (null without contact).
const std::vector<double>* step_pressure(const ContactState& cs) {
  if (cs.fields) return &cs.fields->normal.pressure;
  return cs.pressure;
}

/// The contact's size on the grid from a pressure field: elements with p above a share of the
/// peak (as fields.csv marks them), their extent, and the share of the grid's edge in contact.
ContactSize measure(const Grid& g, const std::vector<double>& p, int& n_contact) {
  double p_max = 0.0;
  for (double v : p)
    if (std::isfinite(v)) p_max = std::max(p_max, v);
  ContactSize size;
  n_contact = 0;
  if (!(p_max > 0.0)) return size;
  const double threshold = 1e-9 * p_max;
  int n_edge = 0, n_edge_contact = 0;
  int i_min = g.nx, i_max = -1, j_min = g.ny, j_max = -1;
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const bool edge = i == 0 || i == g.nx - 1 || (g.dimension == 3 && (j == 0 || j == g.ny - 1));
      n_edge += edge;
      if (!(p[g.index(i, j)] > threshold)) continue;
      ++n_contact;
      n_edge_contact += edge;
      i_min = std::min(i_min, i), i_max = std::max(i_max, i);
      j_min = std::min(j_min, j), j_max = std::max(j_max, j);
    }
  if (n_contact == 0) return size;
  size.across_x = i_max - i_min + 1;
  size.across_y = g.dimension == 3 ? j_max - j_min + 1 : size.across_x;
  size.half_width_x = 0.5 * size.across_x * g.dx;
  size.half_width_y = g.dimension == 3 ? 0.5 * size.across_y * g.dy : 0.0;
  size.edge_fraction = n_edge > 0 ? static_cast<double>(n_edge_contact) / n_edge : 0.0;
  return size;
}

/// The vertical motion of a body whose lowest point starts start_inside (m; negative: above the
/// surface) inside the half-space with the vertical speed v_z (m/s, up positive), under the static
/// downward load P (N): in the potential V(d) = U(d) - P d (V = -P d above the surface), with the
/// Hertz energy U(d) = 2/5 K d^(5/2) (P = K d^(3/2), K = 4/3 E* sqrt(R); Johnson 11.4). A load
/// applied at once to a body resting on the surface swings it to 2.5 P (the deepest approach
/// (5/2)^(2/3) d_s), not to P.
struct VerticalMotion {
  double force = 0.0;     ///< N, K d_max^(3/2) at the deepest approach, V(d_max) = V(d0) + m v^2 / 2; 0: no contact
  double duration = 0.0;  ///< s, the Hertz impact time of the energy at first touch; 0: never released
};

VerticalMotion vertical_motion(double R, double m, double v_z, double start_inside, double P, double E_star) {
  const double K = 4.0 / 3.0 * E_star * std::sqrt(R);
  const auto V = [&](double d) { return d > 0.0 ? 0.4 * K * std::pow(d, 2.5) - P * d : -P * d; };
  // Moving up without a load, the body leaves: its speed does not bring it deeper.
  const double kinetic = v_z < 0.0 || P > 0.0 ? 0.5 * m * v_z * v_z : 0.0;
  const double energy = kinetic + V(start_inside);
  VerticalMotion out;
  if (!(P > 0.0) && !(energy > 0.0)) return out;  // never touches
  // The deepest approach: V rises beyond the static approach d_s = (P / K)^(2/3).
  double lo = std::pow(P / K, 2.0 / 3.0), hi = std::max(lo, start_inside) + 1e-30;
  while (V(hi) < energy) hi *= 2.0;
  for (int it = 0; it < 200 && hi - lo > 1e-15 * hi; ++it) (V(0.5 * (lo + hi)) < energy ? lo : hi) = 0.5 * (lo + hi);
  out.force = K * std::pow(hi, 1.5);
  // Released when it reaches the surface still moving up (V(0) = 0); the static load's part in
  // the contact time is left out, as for an impact.
  if (energy > 0.0) out.duration = hertz::sphere_impact(R, m, std::sqrt(2.0 * energy / m), E_star).duration;
  return out;
}

/// The equivalent radius of a curved 3-D profile's elliptic gap (0: no Hertz estimate).
double equivalent_radius(const ContactSpec& c) {
  if (c.dimension != 3 || c.profile.type == ProfileType::table || c.profile.type == ProfileType::flat_punch)
    return 0.0;
  double A = 0.0, B = 0.0;
  c.profile.quadratic_coefficients(A, B);
  return A > 0.0 && B > 0.0 ? 0.5 / std::sqrt(A * B) : 0.0;
}

/// The vertical motion of a dynamic normal model's body from its initial state.
VerticalMotion vertical_motion(const DynamicSpec& s, double R, double E_star) {
  return vertical_motion(R, s.mass, s.velocity[2], s.radius - s.position[2], std::max(0.0, -s.force[2].value),
                         E_star);
}

}  // namespace

bool dynamic_sizing_load(const DynamicSpec& s, const ContactSpec& c, NormalSpec& load) {
  double P = std::max(0.0, -s.force[2].value);
  if (const double R = equivalent_radius(c); R > 0.0) {
    const double E_star = c.materials.E_star();
    if (s.normal_model == NormalModel::dynamic)  // the deepest approach of the vertical motion
      P = std::max(P, vertical_motion(s, R, E_star).force);
    else if (s.velocity[2] < 0.0)  // the impact at the initial downward speed
      P = std::max(P, hertz::sphere_impact(R, s.mass, -s.velocity[2], E_star).force);
  }
  if (!(P > 0.0) || !std::isfinite(P)) return false;
  load.control = Control::force;
  load.value = P;
  return true;
}

std::optional<DynamicContactEstimate> estimate_dynamic_contact(const DynamicContactSpec& c) {
  if (!c.dynamic || c.fe_body) return std::nullopt;
  const double R = equivalent_radius(c);
  if (!(R > 0.0)) return std::nullopt;
  double A = 0.0, B = 0.0;
  c.profile.quadratic_coefficients(A, B);
  const DynamicSpec& s = *c.dynamic;
  DynamicContactEstimate e;
  NormalSpec load;
  if (dynamic_sizing_load(s, c, load)) {
    e.load = load.value;
    const hertz::EllipticSolution h = hertz::elliptic(A, B, e.load, c.materials.E_star());
    e.approach = h.approach;
    e.half_width_x = h.a;
    e.half_width_y = h.b;
  }
  if (s.normal_model == NormalModel::dynamic) {
    e.start_inside = std::max(0.0, s.radius - s.position[2]);
    // An impact, or the release of a body pressed in: the Hertz impact of its energy at first touch.
    e.contact_time = vertical_motion(s, R, c.materials.E_star()).duration;
  }
  if (e.contact_time > 0.0) e.steps_per_contact = e.contact_time / s.dt;
  return e;
}

std::vector<ResultLimit> dynamic_limits_before(const DynamicContactSpec& c) {
  std::vector<ResultLimit> out;
  const auto e = estimate_dynamic_contact(c);
  if (!e) return out;
  const DynamicSpec& s = *c.dynamic;
  // The contact's own limits first: no time step mends a contact the half-space cannot carry.
  if (e->load > 0.0) {
    const Grid& g = c.grid;
    ContactSize size;
    size.half_width_x = e->half_width_x;
    size.half_width_y = e->half_width_y;
    const bool beyond = e->half_width_x > std::min(-g.x0, g.x_max()) || e->half_width_y > std::min(-g.y0, g.y_max());
    size.edge_fraction = beyond ? 1.0 : 0.0;
    size.across_x = static_cast<int>(2.0 * e->half_width_x / g.dx);
    size.across_y = static_cast<int>(2.0 * e->half_width_y / g.dy);
    const std::string lead =
        e->start_inside > 0.0
            ? format("the Hertz estimate of the largest contact (%.3g N; the body starts %.3g m inside the half-space, "
                     "body.initial.position): ",
                     e->load, e->start_inside)
            : format("the Hertz estimate of the largest contact (%.3g N): ", e->load);
    for (ResultLimit l : result_limits(c, size)) {
      if (l.key == "grid" && beyond)  // an estimate: the share of the edge is not known before the run
        l.message = "the contact reaches beyond the grid: " + l.message.substr(l.message.find(": ") + 2);
      if (l.error) throw InputError(l.key, lead + l.message);
      l.message = lead + l.message;
      out.push_back(l);
    }
  }
  // Adaptive steps: the local error control, not a step count, resolves the contact (time.dt
  // is only the first step).
  if (!s.adaptive && e->contact_time > 0.0 && e->steps_per_contact < kMinStepsPerContact) {
    ResultLimit l{"time.dt",
                  format("%.3g steps of %.3g s in the Hertz contact time of the impact (%.3g s): the peak force "
                         "and the rebound are off by several per cent or more; ",
                         e->steps_per_contact, s.dt, e->contact_time) +
                      format("give time.dt of at most %.3g s (%.0f steps per contact)",
                             e->contact_time / kMinStepsPerContact, kMinStepsPerContact)};
    if (!s.allow_coarse_dt)
      throw InputError("time.dt", l.message + ", or set time.allow_coarse_dt: true to accept it");
    l.message += " (accepted: time.allow_coarse_dt)";
    l.accepted = true;
    out.push_back(l);
  }
  return out;
}

DynamicLimitTracker::DynamicLimitTracker(const DynamicContactSpec& c) : case_(c) {
  if (const auto e = estimate_dynamic_contact(c)) reference_approach_ = e->approach;
}

void DynamicLimitTracker::add(const DynamicSample& s) {
  const ContactState& cs = s.contact_state;
  const std::vector<double>* p = step_pressure(cs);
  int n = 0;
  const ContactSize size = p ? measure(case_.grid, *p, n) : ContactSize{};
  const double time = s.state.time;
  if (size.edge_fraction > worst_edge_fraction_) {
    worst_edge_fraction_ = size.edge_fraction;
    worst_edge_time_ = time;
  }
  if (n > largest_n_) {
    largest_n_ = n;
    largest_ = size;
  }
  // The body's lowest point below the half-space's surface (3-D dynamic normal model: the
  // approach is the body's height, whatever the grid saw).
  const bool height_approach = case_.dimension == 3 && case_.dynamic->normal_model == NormalModel::dynamic;
  if (n > 0) {
    seen_approach_ = std::max(seen_approach_, cs.approach);
    ++episode_steps_;
  } else {
    if (height_approach && cs.approach > unseen_approach_) {
      unseen_approach_ = cs.approach;
      unseen_time_ = time;
    }
    if (episode_steps_ > 0 && (shortest_episode_ == 0 || episode_steps_ < shortest_episode_)) {
      shortest_episode_ = episode_steps_;
      shortest_episode_time_ = time;
    }
    episode_steps_ = 0;
  }
}

std::vector<ResultLimit> DynamicLimitTracker::limits(const DynamicResult& r) const {
  const DynamicContactSpec& c = case_;
  const DynamicSpec& s = *c.dynamic;
  ContactSize size = largest_;
  size.edge_fraction = worst_edge_fraction_;
  std::vector<ResultLimit> out;
  for (ResultLimit l : result_limits(c, size)) {
    if (l.key == "grid" && worst_edge_fraction_ > 0.0)
      l.message = format("at t = %.6g s ", worst_edge_time_) + l.message;
    out.push_back(l);
  }
  // Penetration that no element saw: the grid's elements are coarse against the contact (or
  // the grid does not lie under the body). A first touch between element centres is a small
  // share of the deepest approach; more is a body sinking through a grid that cannot hold it.
  const double reference = std::max(seen_approach_, reference_approach_);
  if (unseen_approach_ > 0.1 * reference + 1e-9 * s.radius)
    out.push_back({"grid",
                   format("at t = %.6g s the body is %.3g m inside the half-space with no element of the grid in "
                          "contact (the deepest approach in contact: %.3g m): the grid's elements are too large "
                          "for the contact and its force is missing; a finer grid (grid.nx, grid.ny) or a smaller "
                          "grid.extent",
                          unseen_time_, unseen_approach_, seen_approach_),
                   true});
  // A contact of a few steps: its force history is not resolved (an impact: the rebound).
  // (Adaptive steps: the error control judges the steps a contact needs.)
  if (!s.adaptive && shortest_episode_ > 0 && shortest_episode_ < kMinStepsPerContact) {
    ResultLimit l{"time.dt",
                  format("a contact ending at t = %.6g s lasted %.0f step(s): its force history is not resolved "
                         "(fewer than %.0f steps per contact); a smaller time.dt",
                         shortest_episode_time_, shortest_episode_, kMinStepsPerContact)};
    if (s.allow_coarse_dt) {
      l.message += " (accepted: time.allow_coarse_dt)";
      l.accepted = true;
    }
    out.push_back(l);
  }
  if (r.steps > 0 && r.energy_imbalance > s.energy_tolerance) {
    const char* key = s.adaptive ? "time.rtol" : "time.dt";
    ResultLimit l{key,
                  format("the energy balance of the run is off by %.3g of the energy (balances.energy; "
                         "time.energy_tolerance %.3g): the time step is too coarse for the contact (or the grid "
                         "too coarse for it); ",
                         r.energy_imbalance, s.energy_tolerance) +
                      std::string(s.adaptive ? "a smaller time.rtol" : "a smaller time.dt") +
                      ", or raise time.energy_tolerance to accept it"};
    l.error = true;
    out.push_back(l);
  }
  return out;
}

}  // namespace dc::dynamics
