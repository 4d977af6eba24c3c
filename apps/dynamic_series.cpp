#include "dynamic_series.hpp"

#include <chrono>
#include <cstdio>
#include <sstream>

#include "fe_body_estimate.hpp"
#include "progress.hpp"
#include "summary_writer.hpp"
#ifdef DYNCONTACT_WITH_FE
#include "elastic_body.hpp"
#include "finite_body_contact.hpp"
#endif

namespace dc::cli {
namespace {

using nlohmann::json;

const char* kColumns =
    "t,x,y,z,vx,vy,vz,wx,wy,wz,Fx,Fy,Fz,Mx,My,Mz,creepage,stick_fraction,approach,contact_area,n_contact,"
    "n_stick,n_slip,kinetic_energy,certificate,newton_iterations\n";

void append_row(std::ostringstream& out, const dynamics::DynamicSample& s) {
  const auto& st = s.state;
  const auto& cs = s.contact_state;
  char line[1024];
  std::snprintf(line, sizeof line,
                "%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.8g,%.8g,%.8g,%.8g,%.8g,%.8g,%.8g,%.6g,"
                "%.8g,%.8g,%d,%d,%d,%.10g,%.3g,%d\n",
                st.time, st.position.x(), st.position.y(), st.position.z(), st.velocity.x(), st.velocity.y(),
                st.velocity.z(), st.omega.x(), st.omega.y(), st.omega.z(), s.contact.force.x(), s.contact.force.y(),
                s.contact.force.z(), s.contact.moment.x(), s.contact.moment.y(), s.contact.moment.z(), cs.creepage,
                cs.stick_fraction, cs.in_contact ? cs.approach : 0.0, cs.contact_area, cs.n_contact, cs.n_stick,
                cs.n_slip, s.kinetic_energy, cs.certificate, s.newton_iterations);
  out << line;
}

json vec(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

}  // namespace

std::vector<DynamicPlotSeries> dynamic_plot_series(int dimension) {
  return {
      {"position", "position (m)", {{2, "x"}, {3, "y"}, {4, "z"}}},
      {"velocity", "velocity (m/s)", {{5, "vx"}, {6, "vy"}, {7, "vz"}}},
      {"omega", "angular velocity (rad/s)", {{8, "wx"}, {9, "wy"}, {10, "wz"}}},
      {"force", "contact force (N)", {{11, "Fx"}, {12, "Fy"}, {13, "Fz"}}},
      {"moment", "contact moment about the centre of mass (N m)", {{14, "Mx"}, {15, "My"}, {16, "Mz"}}},
      {"creepage", "creepage (-)", {{17, "creepage"}}},
      {"stick", "stick fraction of the contact", {{18, "stick_fraction"}}},
      {"approach", "approach (m)", {{19, "approach"}}},
      {"contact_area", dimension == 2 ? "contact length (m)" : "contact area (m^2)", {{20, "contact area"}}},
      {"energy", "kinetic energy (J)", {{24, "kinetic energy"}}},
  };
}

DynamicOutcome simulate_dynamic(const Case& c, bool progress,
                                const std::function<void(const dynamics::DynamicSample&)>& on_step) {
  DynamicOutcome out;
  check_fe_body_fits(c);
#ifdef DYNCONTACT_WITH_FE
  dynamics::DynamicSimulation sim(c, dynamics::make_finite_body(c));
#else
  dynamics::DynamicSimulation sim(c);  // an fe_body: an input error saying how to build with it
#endif
  std::ostringstream series;
  series << kColumns;
  const auto start = std::chrono::steady_clock::now();
  Progress line("dynamic", progress);
  const double t_end = c.dynamic->t_end;
  out.result = sim.run([&](const dynamics::DynamicSample& s) {
    append_row(series, s);
    if (on_step) on_step(s);
    if (progress) line.time(s.state.time, t_end);
  });
  line.finish();
  out.elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  out.timeseries = series.str();

  const dynamics::DynamicResult& r = out.result;
  const auto& sp = *c.dynamic;
  json summary = summary_header(c);
  summary["status"] = r.completed ? "completed" : r.interrupted ? "interrupted" : "stopped";
  summary["message"] = r.status;
  summary["steps"] = r.steps;
  summary["rejected_steps"] = r.rejected_steps;
  summary["final"] = {{"time", r.final.time}, {"position", vec(r.final.position)},
                      {"velocity", vec(r.final.velocity)}, {"omega", vec(r.final.omega)}};
  summary["timeseries"] = "timeseries.csv";
  summary["models"] = {{"normal_model", to_string(sp.normal_model)},
                       {"contact_model", to_string(sp.contact_model)},
                       {"contact_model_used", r.contact_model},
                       {"scheme", sp.bdf2 ? "bdf2" : "bdf1"},
                       {"friction", c.friction ? to_string(c.friction->law) : "none (frictionless)"}};
  summary["solver"] = {{"backend", to_string(c.solver.backend)},
                       {"backends_used", r.backends},
                       {"fallback_steps", r.fallback_steps},
                       {"status", r.completed ? "converged" : "stopped"},
                       {"newton_iterations", r.newton_iterations},
                       {"contact_solves", r.contact_solves},
                       {"time_s", out.elapsed},
                       {"certificate", {{"worst", r.worst_certificate}, {"last", r.last_certificate}}}};
  summary["balances"] = {{"momentum", r.momentum_imbalance}, {"energy", r.energy_imbalance}};
  out.limits = r.limits;
  summary["limits"] = limits_json(out.limits);
#ifdef DYNCONTACT_WITH_FE
  if (const dynamics::FiniteBody* body = sim.finite_body()) {  // as for problem "finite"
    summary["body_dofs"] = body->elastic_body().dofs();
    summary["body_elements"] = body->elastic_body().mesh().elements.size();
    summary["max_body_displacement"] = body->max_displacement();
    summary["mesh_time_s"] = body->mesh_seconds();
    summary["factorisation_time_s"] = body->elastic_body().factorisation_seconds();
    summary["body"] = {{"mass", sim.body().mass()},
                       {"inertia", {sim.body().inertia_body()(0, 0), sim.body().inertia_body()(1, 1),
                                    sim.body().inertia_body()(2, 2)}},
                       {"radius", body->centre_height()}};
  }
#endif
  out.summary = std::move(summary);
  return out;
}

}  // namespace dc::cli
