#include "paper_cylinder_run.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <sstream>
#include <vector>

#include "errors.hpp"
#include "exit_codes.hpp"
#include "gnuplot_figures.hpp"
#include "hertz.hpp"
#include "interrupt.hpp"
#include "interrupt_handler.hpp"
#include "output_files.hpp"
#include "paper_cylinder.hpp"
#include "profile.hpp"
#include "progress.hpp"
#include "summary_writer.hpp"
#include "table_ranks.hpp"
#include "tangential_problem.hpp"

namespace dc::runs {
namespace {

using nlohmann::json;
namespace pc = paper_cylinder;

/// The dimensionless inputs as given, on the model's defaults.
pc::Parameters parameters_of(const PaperCylinderSpec& s) {
  pc::Parameters p;
  auto set = [](const std::optional<double>& v, double& out) {
    if (v) out = *v;
  };
  set(s.gamma_bar, p.gamma_bar);
  set(s.M0_bar, p.M0_bar);
  set(s.eta, p.eta);
  set(s.epsilon, p.epsilon);
  set(s.v_bar0, p.v_bar0);
  set(s.t_bar_end, p.t_bar_end);
  set(s.T_bar, p.T_bar);
  set(s.mu, p.mu);
  return p;
}

/// The paper's scales of one run: what one unit of t^, x^, u, F/(mu P), M/(mu P R) is in SI
/// (dimensional inputs), or 1 with the dimensionless ones (mu then known only if friction gives it).
struct Units {
  bool dimensional = false;
  double time = 1.0, length = 1.0, velocity = 1.0, force = 1.0, moment = 1.0;  // M V0/(mu P), V0 time, V0, mu P, mu P R
  double radius = 1.0;      ///< R (1: omega reported as Omega R / V0)
  double mu = 0.0;          ///< 0: unknown
  double x0 = 0.0, z0 = 0.0;
};

/// Dimensional inputs (body, loads, materials, friction, time; per unit length in 2-D) turned
/// into the paper's dimensionless ones. The contact half-width is Hertz's for the pair,
/// a = (4 P R / (pi E*))^(1/2) ((5.4) is that for a rigid cylinder: E* = E/(1 - nu^2)).
pc::Parameters dimensional_parameters(const Case& c, Units& u, double& dt_bar) {
  const PaperCylinderBody& b = c.paper_cylinder->body;
  const double M = b.mass, R = b.radius, I = b.inertia_y;
  const double V0 = b.velocity[0], W0 = b.omega[1];
  const double P = -b.force_z.value, T = b.force_x.value;
  const double M0 = b.moment_y.value, gamma = b.moment_y.rate;
  const double mu = c.friction->mu;
  const double a = hertz::cylinder2d(R, P, c.materials.E_star()).a;
  pc::Parameters p;
  p.epsilon = a / R;
  p.mu = mu;
  p.eta = M * R * R / I;
  p.gamma_bar = gamma * M * V0 / (mu * P * mu * P * R);
  p.M0_bar = M0 / (mu * P * R);
  p.T_bar = T / (mu * P);
  p.w0 = (V0 - W0 * R) / (mu * p.epsilon * V0);
  u.dimensional = true;
  u.time = M * V0 / (mu * P);
  u.velocity = V0;
  u.length = V0 * u.time;
  u.force = mu * P;
  u.moment = mu * P * R;
  u.radius = R;
  u.mu = mu;
  u.x0 = b.position[0];
  u.z0 = b.has_position ? b.position[2] : R;
  p.t_bar_end = b.t_end / u.time;
  dt_bar = b.dt / u.time;
  return p;
}

struct TimeSpec {
  double dt = 0.0;
  pc::Scheme scheme = pc::Scheme::bdf1;
};

/// One run's inputs: dimensionless, or dimensional converted (the units say which).
struct Setup {
  bool mu_given = false;
  pc::Parameters p;
  Units units;
  TimeSpec time;
};

Setup setup_of(const Case& c) {
  const PaperCylinderSpec& spec = *c.paper_cylinder;
  Setup s;
  s.time.scheme = spec.bdf2 ? pc::Scheme::bdf2 : pc::Scheme::bdf1;
  if (!spec.dimensional) {
    s.p = parameters_of(spec);
    // dimensionless: time.dt is a step of t^ (default t_bar_end / 1000).
    s.time.dt = spec.dt ? *spec.dt : s.p.t_bar_end / 1000.0;
    // mu sets the slip's relaxation (mu eps); dimensionless.mu (project extension), else
    // friction.mu, else 1 (said in the summary).
    const bool in_block = spec.mu.has_value();
    if (!in_block && c.friction && c.friction->law == FrictionLawKind::coulomb) s.p.mu = c.friction->mu;
    s.mu_given = in_block || (c.friction && c.friction->law == FrictionLawKind::coulomb);
    s.units.mu = s.mu_given ? s.p.mu : 0.0;
  } else {
    s.p = dimensional_parameters(c, s.units, s.time.dt);
    s.mu_given = true;
  }
  pc::check(s.p);
  return s;
}

/// The creep law F/(mu P) of s computed by the tangential solver: steady rolling of a 2-D
/// cylinder (the case's materials, profile radius, normal force, friction and grid.nx when
/// given; steel, R = 0.05 m, 1e5 N/m, mu = 0.3, 200 strips otherwise) at creepage
/// xi = s mu a / R, tabulated on |s| <= 1 and interpolated linearly. The case's backend (auto:
/// steady Newton, marching with native first and the others as fallbacks); `backends` counts the
/// table's points per backend that solved them, `fallbacks` those that needed a fallback.
pc::TractionLaw numerical_law(const Case& c, std::map<std::string, int>& backends, int& fallbacks) {
  const MaterialPair m = c.has_block("materials") ? c.materials
                                                   : MaterialPair{Elastic::from_E_nu(2.1e11, 0.3),
                                                                  Elastic::from_E_nu(2.1e11, 0.3)};
  const double R = c.has_block("profile") && c.profile.radius > 0.0 ? c.profile.radius : 0.05;
  const double P = c.has_block("normal") && c.normal.control == Control::force ? c.normal.value : 1e5;
  const double mu = c.friction && c.friction->law == FrictionLawKind::coulomb ? c.friction->mu : 0.3;
  const int nx = c.has_block("grid") ? c.grid.nx : 200;
  const auto hz = hertz::cylinder2d(R, P, m.E_star());
  const Grid g = Grid::make(2, nx, 1, -1.2 * hz.a, 1.2 * hz.a, 0, 0);
  ProfileSpec prof;
  prof.type = ProfileType::cylinder;
  prof.radius = R;
  TangentialProblem problem(g, m, profile_heights(prof, g), FrictionLaw::coulomb(mu));
  const SolverOptions& solver = c.solver;
  const int K = 100;
  auto table = std::make_shared<std::vector<double>>(K + 1, 0.0);
  for (int k = 1; k <= K; ++k) {
    RollingLoad load;
    load.normal = {Control::force, P};
    const double s = static_cast<double>(k) / K;
    load.modes = {ModeControl{ModeControl::Kind::amplitude, s * mu * hz.a / R}, ModeControl{}, ModeControl{}};
    const TangentialSolution sol = problem.steady_rolling(load, solver);
    if (sol.report.status != SolveStatus::converged)
      throw std::runtime_error("numerical traction: steady rolling at s = " + std::to_string(s) +
                               " did not converge: " + sol.report.message);
    ++backends[sol.report.backend];
    if (sol.report.fallback_used) ++fallbacks;
    (*table)[k] = -sol.resultants[0] / (mu * P);  // the paper's F is the force on the substrate
  }
  pc::TractionLaw law;
  auto segment = [table](double a, int& k, double& f) {
    const double x = std::min(a, 1.0) * K;
    k = std::min(static_cast<int>(x), K - 1);
    f = x - k;
  };
  law.force_ratio = [table, segment](double s) {
    int k;
    double f;
    segment(std::abs(s), k, f);
    const double v = std::abs(s) >= 1.0 ? (*table)[K] : (1.0 - f) * (*table)[k] + f * (*table)[k + 1];
    return s < 0.0 ? -v : v;
  };
  law.slope = [table, segment](double s) {
    if (std::abs(s) >= 1.0) return 0.0;
    int k;
    double f;
    segment(std::abs(s), k, f);
    return ((*table)[k + 1] - (*table)[k]) * K;
  };
  return law;
}

std::string fmt(double v) {
  if (v == 0.0) v = 0.0;  // no "-0"
  char b[32];
  std::snprintf(b, sizeof b, "%.9g", v);
  return b;
}

/// timeseries.csv of the contract (SI for dimensional inputs; else in the paper's units: t in
/// M V0/(mu P), x in M V0^2/(mu P), velocities in V0, forces in mu P, moments in mu P R, omega as
/// Omega R / V0 - the columns that need mu itself are left empty unless friction.mu is given).
/// F and M are the contact wrench on the body about its centre: F_x = -F, F_z = P, M_y = F R.
std::string timeseries_text(const pc::Run& run, const pc::Parameters& p, const Units& u, const pc::TractionLaw& law) {
  std::ostringstream out;
  out << "t,x,y,z,vx,vy,vz,wx,wy,wz,Fx,Fy,Fz,Mx,My,Mz,creepage,stick_fraction,t_bar,F_bar,l_bar,v_bar\n";
  const bool has_mu = u.mu > 0.0;
  double x = 0.0;
  for (std::size_t k = 0; k < run.samples.size(); ++k) {
    const pc::Sample& s = run.samples[k];
    if (k > 0) x += 0.5 * (s.u + run.samples[k - 1].u) * (s.t_bar - run.samples[k - 1].t_bar);
    const double ratio = s.w / s.u, phi = law.force_ratio(ratio);
    out << fmt(s.t_bar * u.time) << ',' << fmt(u.x0 + x * u.length) << ",0," << fmt(u.z0) << ','
        << fmt(s.u * u.velocity) << ",0,0,0,"
        << (has_mu ? fmt((s.u - u.mu * p.epsilon * s.w) * u.velocity / u.radius) : "") << ",0,"
        << fmt(-phi * u.force) << ",0," << (has_mu ? fmt(u.force / u.mu) : "") << ",0," << fmt(phi * u.moment)
        << ",0," << (has_mu ? fmt(u.mu * p.epsilon * ratio) : "") << ',' << fmt(s.l_bar) << ',' << fmt(s.t_bar)
        << ',' << fmt(s.F_bar) << ',' << fmt(s.l_bar) << ',' << fmt(s.v_bar) << '\n';
  }
  return out.str();
}

json final_of(const pc::Run& run, const pc::Parameters& p, const Units& u) {
  const pc::Sample& s = run.samples.back();
  double x = 0.0;
  for (std::size_t k = 1; k < run.samples.size(); ++k)
    x += 0.5 * (run.samples[k].u + run.samples[k - 1].u) * (run.samples[k].t_bar - run.samples[k - 1].t_bar);
  const json omega = u.mu > 0.0 ? json{0.0, (s.u - u.mu * p.epsilon * s.w) * u.velocity / u.radius, 0.0} : json();
  return {{"time", s.t_bar * u.time}, {"position", {u.x0 + x * u.length, 0.0, u.z0}},
          {"velocity", {s.u * u.velocity, 0.0, 0.0}}, {"omega", omega}, {"t_bar", s.t_bar}, {"F_bar", s.F_bar},
          {"l_bar", s.l_bar}, {"v_bar", s.v_bar}, {"sliding", s.sliding}};
}

}  // namespace

void validate_paper_cylinder(const Case& c) {
  (void)setup_of(c);
  for (const SweepPoint& r : sweep_points(c)) (void)setup_of(r.run);
}

namespace {

/// The largest value in column `index` (0-based) of a CSV text with a header line.
double column_max(const std::string& csv, std::size_t index) {
  std::istringstream in(csv);
  std::string line, cell;
  std::getline(in, line);  // the header
  double best = 0.0;
  while (std::getline(in, line)) {
    std::istringstream row(line);
    for (std::size_t k = 0; k <= index && std::getline(row, cell, ','); ++k) {
    }
    best = std::max(best, std::strtod(cell.c_str(), nullptr));
  }
  return best;
}

/// One run of the sweep (a work unit of run_distributed): {"started", "ok", "interrupted", "run"
/// (its entry of summary "runs"), "timeseries" (the CSV text), "line" (the report line)}.
json sweep_unit(const Case& c, const std::vector<SweepPoint>& specs, std::size_t k) {
  const Case& run_case = specs[k].run;
  const Setup setup = setup_of(run_case);
  const pc::Parameters& p = setup.p;
  pc::TractionLaw law;
  std::map<std::string, int> law_backends;
  int law_fallbacks = 0;
  try {
    if (c.paper_cylinder->traction_model == "numerical") law = numerical_law(run_case, law_backends, law_fallbacks);
  } catch (const Interrupted&) {  // before this run's first step
    return {{"started", false}, {"ok", false}, {"interrupted", true}};
  }
  const pc::Run run = pc::simulate(p, setup.time.dt, setup.time.scheme, law);
  const std::string file = specs.size() == 1 ? "timeseries.csv" : "timeseries_" + std::to_string(k) + ".csv";
  double onset = -1.0;
  for (const pc::Sample& s : run.samples)
    if (s.sliding) {
      onset = s.t_bar;
      break;
    }
  const pc::Sample q = pc::quasi_static(p, run.samples.back().t_bar);
  const char* status = run.ok ? "completed" : run.interrupted ? "interrupted" : "stopped";
  json r = {{"label", specs[k].label}, {"value", specs[k].value}, {"status", status},
            {"message", run.message}, {"steps", static_cast<int>(run.samples.size()) - 1},
            {"final", final_of(run, p, setup.units)}, {"timeseries", file}, {"dt_bar", setup.time.dt},
            {"dimensionless", {{"gamma_bar", p.gamma_bar}, {"M0_bar", p.M0_bar},
                               {"eta", std::isinf(p.eta) ? json("inf") : json(p.eta)}, {"epsilon", p.epsilon},
                               {"T_bar", p.T_bar}, {"t_bar_end", p.t_bar_end},
                               {"mu", setup.mu_given ? json(p.mu) : json("1 (not given)")}}},
            {"sliding_onset_t_bar", onset >= 0.0 ? json(onset) : json()},
            {"quasi_static_final", std::abs(p.T_bar) == 0.0 && !q.sliding
                                       ? json{{"F_bar", q.F_bar}, {"l_bar", q.l_bar}, {"v_bar", q.v_bar}, {"u", q.u}}
                                       : json()}};
  if (c.paper_cylinder->traction_model == "numerical")
    r["traction_solver"] = {{"backends_used", law_backends}, {"fallback_points", law_fallbacks}};
  const pc::Sample& s = run.samples.back();
  char line[512];
  std::snprintf(line, sizeof line, "%s%s%s: t_bar %.4g, F_bar %.5f, l_bar %.5f, v_bar %.5g%s%s\n", c.name.c_str(),
                specs[k].label.empty() ? "" : " ", specs[k].label.c_str(), s.t_bar, s.F_bar, s.l_bar, s.v_bar,
                onset >= 0.0 ? (", gross sliding from t_bar " + fmt(onset)).c_str() : "",
                run.ok ? "" : (" [stopped: " + run.message + "]").c_str());
  return {{"started", true}, {"ok", run.ok}, {"interrupted", run.interrupted}, {"run", r},
          {"timeseries", timeseries_text(run, p, setup.units, law)}, {"line", line}};
}

}  // namespace

PaperCylinderOutcome simulate_paper_cylinder(const Case& c, bool quiet) {
  validate_paper_cylinder(c);
  const std::vector<SweepPoint> specs = sweep_points(c);
  const Setup first = setup_of(c);
  const table::LaunchRank launched = table::launch_rank();

  // The runs over the cores or the ranks (table/table_ranks.hpp), gathered in sweep order.
  Progress progress("sweep", launched.root() && !quiet && specs.size() > 1);
  const std::vector<json> units = table::run_distributed(
      specs.size(), [&](std::size_t k) { return sweep_unit(c, specs, k); },
      [&](std::size_t done, std::size_t total) { progress.count(done, total, "runs"); });
  progress.finish();
  PaperCylinderOutcome out;
  out.root = launched.root();
  if (!out.root) return out;

  json summary = {{"name", c.name},
                  {"problem", "paper_cylinder"},
                  {"traction_model", c.paper_cylinder->traction_model},
                  {"inputs", first.units.dimensional ? "dimensional" : "dimensionless"},
                  {"scheme", first.time.scheme == pc::Scheme::bdf2 ? "bdf2" : "bdf1"}};
  json runs = json::array();
  for (std::size_t k = 0; k < units.size() && !out.interrupted; ++k) {
    const json& u = units[k];
    if (u.is_null()) {  // not run to its end (interrupted): the runs before it
      out.interrupted = true;
      break;
    }
    if (u.contains("error")) {  // a run that failed (e.g. its numerical traction): reported, the others kept
      runs.push_back({{"label", specs[k].label}, {"value", specs[k].value}, {"status", "failed"},
                      {"message", u["error"]}, {"steps", 0}, {"timeseries", nullptr}});
      out.all_ok = false;
      std::cerr << "error: " << c.name << (specs[k].label.empty() ? "" : " ") << specs[k].label
                << ": failed: " << u["error"].get<std::string>() << '\n';
      continue;
    }
    if (!u["started"].get<bool>()) {  // interrupted before its first step: the runs before it
      out.interrupted = true;
      break;
    }
    out.interrupted = u["interrupted"].get<bool>();
    runs.push_back(u["run"]);
    out.files.push_back(u["run"]["timeseries"].get<std::string>());
    out.texts.push_back(u["timeseries"].get<std::string>());
    out.labels.push_back(specs[k].label.empty() ? c.name : specs[k].label);
    out.all_ok = out.all_ok && u["ok"].get<bool>();
    if (!quiet) std::printf("%s", u["line"].get<std::string>().c_str());
  }
  if (!runs.empty()) {
    summary["steps"] = runs[0]["steps"];
    if (runs[0].contains("final")) summary["final"] = runs[0]["final"];
    summary["timeseries"] = runs[0]["timeseries"];
  }
  summary["status"] = out.interrupted ? "interrupted" : out.all_ok ? "completed" : "stopped";
  if (specs.size() > 1 || !specs[0].label.empty()) summary["runs"] = runs;
  else if (!runs.empty()) summary["run"] = runs[0];
  out.summary = std::move(summary);
  out.planned = specs.size();
  return out;
}

int run_paper_cylinder(const Case& c, const std::string& dir, bool quiet) {
  PaperCylinderOutcome out = simulate_paper_cylinder(c, quiet);
  if (!out.root) return kExitOk;
  namespace fs = std::filesystem;
  for (std::size_t k = 0; k < out.files.size(); ++k)
    output::write_file_whole((fs::path(dir) / out.files[k]).string(), out.texts[k]);
  json& summary = out.summary;
  const bool interrupted = out.interrupted, all_ok = out.all_ok;
  json out_files = {{"summary", "summary.json"}, {"timeseries", out.files}};
  const std::vector<std::string>& files = out.files;
  const std::vector<std::string>& labels = out.labels;

  if (c.output.plots && !interrupted) {  // an interrupted run writes its data, not figures
    std::vector<output::GnuplotFigure> figures;
    const char* names[][3] = {{"F_bar", "20", "friction force |F|/({/Symbol m}P)"},
                              {"l_bar", "21", "adhesion half-length 1 - d/l"},
                              {"v_bar", "22", "rigid-slip velocity |v|/({/Symbol m}{/Symbol e}V(0))"}};
    // Gross sliding makes v^ of order 1/epsilon (10^3-10^4), which flattens the pre-sliding part
    // (v^ of order 1) to zero on a linear axis: then v^ is drawn on a log axis.
    double v_max = 0.0;
    for (const std::string& text : out.texts) v_max = std::max(v_max, column_max(text, 21));
    for (const auto& n : names) {
      const bool log_axis = std::string(n[0]) == "v_bar" && v_max > 10.0;
      std::ostringstream b;
      b << "set datafile separator \",\"\nset key top left noenhanced\nset grid\n"
        << "set xlabel \"time  t {/Symbol m}P / (M V(0))\"\n"
        << (log_axis ? "set logscale y\nset format y \"10^{%T}\"\n" : "set yrange [0:*]\n") << "set ylabel \""
        << n[2] << (log_axis ? " (log scale)" : "") << "\"\n"
        << "set title \"" << c.name << "\" noenhanced\nplot ";
      for (std::size_t k = 0; k < files.size(); ++k)
        b << (k ? ", " : "") << "\"" << files[k] << "\" using 19:" << n[1] << " skip 1 with lines lw 2 title \""
          << labels[k] << "\"";
      b << "\n";
      figures.push_back({n[0], b.str()});
    }
    json plots = json::array();
    for (const auto& img : output::render_gnuplot(dir, c.name, figures))
      plots.push_back(fs::path(img).filename().string());
    out_files["plots"] = plots;
  }
  summary["files"] = out_files;
  const std::string path = output::write_summary(dir, summary);
  if (!quiet) std::printf("wrote %s\n", path.c_str());
  if (interrupted) {
    std::cerr << "interrupted after " << out.files.size() << " of " << out.planned
              << " run(s) (the last may be partial); see " << path << '\n';
    return interrupted_exit_code();
  }
  if (!all_ok) {
    std::cerr << "error: a run stopped early (see " << path << ")\n";
    return kExitUnconverged;
  }
  return kExitOk;
}

}  // namespace dc::runs
