#include "table_points.hpp"

#include <cmath>
#include <exception>
#include <limits>

#include "errors.hpp"
#include "solve_case.hpp"
#include "tangential_problem.hpp"

namespace dc::table {
namespace {

nlohmann::json row_json(const TangentialSolution& s, double area) {
  double capacity = 0.0;  // sum f(p) A: mu P for Coulomb friction
  for (double f : s.bound) capacity += f * area;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  nlohmann::json r = {{"Fx", s.resultants[0]},
                      {"Fy", s.resultants[1]},
                      {"Mz", s.resultants[2]},
                      {"Fx_mu_P", capacity > 0.0 ? s.resultants[0] / capacity : nan},
                      {"Fy_mu_P", capacity > 0.0 ? s.resultants[1] / capacity : nan},
                      {"n_stick", s.n_stick},
                      {"certificate", s.report.certificate.worst()},
                      {"status", to_string(s.report.status)}};
  if (s.report.status != SolveStatus::converged) r["message"] = s.report.message;
  // A result that is not a number is never a converged point, whatever the solver said.
  for (const char* key : {"Fx", "Fy", "Mz"})
    if (!std::isfinite(r[key].get<double>())) return {{"status", "failed"}, {"message", "the solver returned no finite forces"}};
  return r;
}

/// A number of a row; JSON has no NaN (a NaN is written as null): null reads back as NaN.
double number(const nlohmann::json& r, const char* key) {
  const auto& v = r.at(key);
  return v.is_number() ? v.get<double>() : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

void check_table_case(const Case& c, const TableAxes& axes) {
  if (c.problem != ProblemKind::tangential || !c.tangential)
    throw InputError("problem", "a creep-force table needs a tangential case with \"regime\": \"rolling\"");
  if (c.tangential->regime != TangentialRegime::rolling)
    throw InputError("tangential.regime", "a creep-force table needs steady rolling (\"rolling\"), not '" +
                                              std::string(to_string(c.tangential->regime)) + "'");
  if (c.tangential->has_history)
    throw InputError("tangential.history", "a creep-force table is steady rolling: remove the rolling history");
  if (c.dimension == 2) {
    for (double v : axes.creepage_y)
      if (v != 0.0) throw InputError("--lateral", "a 2-D (plane strain) case has no lateral creepage");
    for (double v : axes.spin)
      if (v != 0.0) throw InputError("--spin", "a 2-D (plane strain) case has no spin");
  }
  if (axes.size() == 0) throw InputError("--creepage", "the table has no points");
  // A table holds forces only: blocks that ask for more would be silently left out.
  const char* beyond_forces = c.subsurface.enabled   ? "subsurface"
                              : c.yields.base        ? "materials.base.yield"
                              : c.yields.body        ? "materials.body.yield"
                              : c.fatigue.base       ? "materials.base.fatigue"
                              : c.fatigue.body       ? "materials.body.fatigue"
                              : c.shakedown          ? "shakedown"
                              : c.thermal.base       ? "materials.base.thermal"
                              : c.thermal.body       ? "materials.body.thermal"
                              : c.accuracy.target    ? "accuracy.target"
                                                     : nullptr;
  if (beyond_forces)
    throw InputError(beyond_forces, "a creep-force table gives the forces of each point only; solve the point "
                                    "with `dyncontact solve` for this");
}

nlohmann::json solve_table_line(const Case& c, const TableAxes& axes, std::size_t line) {
  TangentialProblem problem = make_tangential_problem(c);
  RollingLoad load = c.tangential->rolling;
  const double cy = axes.creepage_y[line % axes.creepage_y.size()];
  const double spin = axes.spin[line / axes.creepage_y.size()];
  nlohmann::json rows = nlohmann::json::array();
  for (double cx : axes.creepage_x) {
    const double values[3] = {cx, cy, spin};
    for (int k = 0; k < 3; ++k) load.modes[k] = {ModeControl::Kind::amplitude, values[k]};
    try {
      TangentialSolution s = problem.steady_rolling(load, c.solver);
      // A warm start across the saturation (full slip → stick) can leave Newton short of the
      // steady state: the point is then solved again from a fresh problem and zero traction.
      if (s.report.status != SolveStatus::converged && !load.warm_start.empty()) {
        problem = make_tangential_problem(c);
        load.warm_start.clear();
        s = problem.steady_rolling(load, c.solver);
      }
      rows.push_back(row_json(s, c.grid.area()));
      // The next point starts from this one's traction when it is a proven steady state.
      if (rows.back()["status"] == "converged") {
        load.warm_start = rolling_warm_start(s, c.dimension);
        continue;
      }
    } catch (const std::exception& e) {
      rows.push_back({{"status", "failed"}, {"message", e.what()}});
    }
    // After a failure: a fresh problem and zero traction, so that nothing of it carries over.
    problem = make_tangential_problem(c);
    load.warm_start.clear();
  }
  return rows;
}

std::vector<TableRow> rows_from_line(const TableAxes& axes, std::size_t line, const nlohmann::json& result) {
  const double cy = axes.creepage_y[line % axes.creepage_y.size()];
  const double spin = axes.spin[line / axes.creepage_y.size()];
  std::vector<TableRow> rows(axes.creepage_x.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    TableRow& row = rows[i];
    row.creepage_x = axes.creepage_x[i];
    row.creepage_y = cy;
    row.spin = spin;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    row.Fx = row.Fy = row.Mz = row.Fx_mu_P = row.Fy_mu_P = row.certificate = nan;
    const nlohmann::json* r = result.is_array() && i < result.size() ? &result[i] : nullptr;
    if (!r) {
      row.message = result.is_object() && result.contains("error") ? result["error"].get<std::string>()
                                                                   : "no result for this point";
      continue;
    }
    row.status = r->at("status").get<std::string>();
    if (r->contains("message")) row.message = r->at("message").get<std::string>();
    if (row.status == "failed") continue;
    row.Fx = number(*r, "Fx");
    row.Fy = number(*r, "Fy");
    row.Mz = number(*r, "Mz");
    row.Fx_mu_P = number(*r, "Fx_mu_P");
    row.Fy_mu_P = number(*r, "Fy_mu_P");
    row.certificate = number(*r, "certificate");
    row.n_stick = r->at("n_stick").get<int>();
  }
  return rows;
}

}  // namespace dc::table
