#include "paper_cylinder_run.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <limits>
#include <memory>
#include <set>
#include <sstream>
#include <vector>

#include "cli_common.hpp"
#include "errors.hpp"
#include "gnuplot_figures.hpp"
#include "hertz.hpp"
#include "paper_cylinder.hpp"
#include "profile.hpp"
#include "summary_writer.hpp"
#include "tangential_problem.hpp"

namespace dc::cli {
namespace {

using nlohmann::json;
namespace pc = paper_cylinder;

double number(const json& v, const std::string& key) {
  if (!v.is_number()) throw InputError(key, "must be a number");
  const double x = v.get<double>();
  if (!std::isfinite(x)) throw InputError(key, "must be finite");
  return x;
}

void check_keys(const json& v, const std::string& block, const std::set<std::string>& allowed) {
  for (auto it = v.begin(); it != v.end(); ++it)
    if (!allowed.count(it.key())) throw InputError(block + "." + it.key(), "unknown key");
}

pc::Parameters parameters_of(const json& doc) {
  if (!doc.contains("dimensionless"))
    throw InputError("dimensionless",
                     "required: the paper's dimensionless inputs, or the dimensional blocks body, loads, time");
  const json& d = doc.at("dimensionless");
  if (!d.is_object()) throw InputError("dimensionless", "expected an object");
  check_keys(d, "dimensionless", {"gamma_bar", "M0_bar", "eta", "epsilon", "v_bar0", "t_bar_end", "T_bar", "mu"});
  pc::Parameters p;
  auto get = [&](const char* k, double& out) {
    if (d.contains(k)) out = number(d.at(k), std::string("dimensionless.") + k);
  };
  get("gamma_bar", p.gamma_bar);
  get("M0_bar", p.M0_bar);
  get("epsilon", p.epsilon);
  get("v_bar0", p.v_bar0);
  get("t_bar_end", p.t_bar_end);
  get("T_bar", p.T_bar);
  get("mu", p.mu);
  if (d.contains("eta")) {
    const json& e = d.at("eta");
    if (e.is_string() && e.get<std::string>() == "inf") p.eta = std::numeric_limits<double>::infinity();
    else p.eta = number(e, "dimensionless.eta");
  }
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

const json& member(const json& v, const std::string& key, const std::string& name) {
  if (!v.is_object() || !v.contains(name)) throw InputError(key.empty() ? name : key + "." + name, "missing required key");
  return v.at(name);
}

/// {"value": v, "rate": r} (rate optional) at `key`.
std::pair<double, double> value_rate(const json& v, const std::string& key) {
  if (!v.is_object()) throw InputError(key, "expected {\"value\": ..., \"rate\": ...}");
  check_keys(v, key, {"value", "rate"});
  return {v.contains("value") ? number(v.at("value"), key + ".value") : 0.0,
          v.contains("rate") ? number(v.at("rate"), key + ".rate") : 0.0};
}

/// Dimensional inputs (body, loads, materials, friction, time; per unit length in 2-D) turned
/// into the paper's dimensionless ones. The contact half-width is Hertz's for the pair,
/// a = (4 P R / (pi E*))^(1/2) ((5.4) is that for a rigid cylinder: E* = E/(1 - nu^2)).
pc::Parameters dimensional_parameters(const Case& c, const json& doc, Units& u, double& dt_bar) {
  const json& body = member(doc, "", "body");
  check_keys(body, "body", {"mass", "inertia", "radius", "initial"});
  const double M = number(member(body, "body", "mass"), "body.mass");
  const double R = number(member(body, "body", "radius"), "body.radius");
  const json& inertia = member(body, "body", "inertia");
  const double I = inertia.is_array() && inertia.size() == 3 ? number(inertia[1], "body.inertia[1]")
                                                             : number(inertia, "body.inertia");
  if (!(M > 0.0)) throw InputError("body.mass", "must be positive");
  if (!(R > 0.0)) throw InputError("body.radius", "must be positive");
  if (!(I > 0.0)) throw InputError("body.inertia", "the moment of inertia about the axis (y) must be positive");
  const json& init = member(body, "body", "initial");
  check_keys(init, "body.initial", {"position", "velocity", "omega"});
  auto vec = [&](const char* k, int i) {
    if (!init.contains(k)) return 0.0;
    const json& a = init.at(k);
    if (!a.is_array() || a.size() != 3) throw InputError(std::string("body.initial.") + k, "must be [x, y, z]");
    return number(a[i], std::string("body.initial.") + k + "[" + std::to_string(i) + "]");
  };
  const double V0 = vec("velocity", 0), W0 = vec("omega", 1);
  if (!(V0 > 0.0)) throw InputError("body.initial.velocity[0]", "the cylinder must be rolling in +x (V0 > 0)");
  const json& loads = member(doc, "", "loads");
  check_keys(loads, "loads", {"force", "moment"});
  const json& force = member(loads, "loads", "force");
  check_keys(force, "loads.force", {"x", "z"});
  const auto [Pz, Pz_rate] = value_rate(member(force, "loads.force", "z"), "loads.force.z");
  const auto [T, T_rate] = force.contains("x") ? value_rate(force.at("x"), "loads.force.x") : std::pair{0.0, 0.0};
  const json& moment = member(loads, "loads", "moment");
  check_keys(moment, "loads.moment", {"y"});
  const auto [M0, gamma] = value_rate(member(moment, "loads.moment", "y"), "loads.moment.y");
  if (Pz_rate != 0.0) throw InputError("loads.force.z.rate", "the paper's model keeps the normal load constant");
  if (T_rate != 0.0) throw InputError("loads.force.x.rate", "the paper's model takes a constant T_ex");
  const double P = -Pz;
  if (!(P > 0.0)) throw InputError("loads.force.z.value", "must press the cylinder onto the half-plane (< 0)");
  if (!c.friction || c.friction->law != "coulomb")
    throw InputError("friction", "the paper's model needs Coulomb friction {\"law\": \"coulomb\", \"mu\": ...}");
  if (!doc.contains("materials")) throw InputError("materials", "missing required key");
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
  u.x0 = vec("position", 0);
  u.z0 = init.contains("position") ? vec("position", 2) : R;
  const json& time = member(doc, "", "time");
  check_keys(time, "time", {"dt", "t_end", "scheme"});
  const double t_end = number(member(time, "time", "t_end"), "time.t_end");
  const double dt = number(member(time, "time", "dt"), "time.dt");
  if (!(t_end > 0.0)) throw InputError("time.t_end", "must be positive");
  if (!(dt > 0.0)) throw InputError("time.dt", "must be positive");
  p.t_bar_end = t_end / u.time;
  dt_bar = dt / u.time;
  return p;
}

struct TimeSpec {
  double dt = 0.0;
  pc::Scheme scheme = pc::Scheme::bdf1;
};

pc::Scheme scheme_of(const json& doc) {
  if (!doc.contains("time") || !doc.at("time").contains("scheme")) return pc::Scheme::bdf1;
  const json& v = doc.at("time").at("scheme");
  const std::string s = v.is_string() ? v.get<std::string>() : "";
  if (s != "bdf1" && s != "bdf2") throw InputError("time.scheme", "must be \"bdf1\" or \"bdf2\"");
  return s == "bdf2" ? pc::Scheme::bdf2 : pc::Scheme::bdf1;
}

/// Dimensionless inputs: time.dt is a step of t^ (default t_bar_end / 1000).
TimeSpec time_of(const json& doc, const pc::Parameters& p) {
  TimeSpec t;
  t.dt = p.t_bar_end / 1000.0;
  t.scheme = scheme_of(doc);
  if (!doc.contains("time")) return t;
  const json& b = doc.at("time");
  check_keys(b, "time", {"dt", "scheme"});
  if (b.contains("dt")) t.dt = number(b.at("dt"), "time.dt");
  if (!(t.dt > 0.0)) throw InputError("time.dt", "must be positive (a step of t_bar for dimensionless inputs)");
  return t;
}

/// One run's inputs: dimensionless, or dimensional converted (the units say which).
struct Setup {
  bool mu_given = false;
  pc::Parameters p;
  Units units;
  TimeSpec time;
};

Setup setup_of(const Case& c, const json& doc) {
  Setup s;
  if (doc.contains("dimensionless") || !doc.contains("body")) {
    s.p = parameters_of(doc);
    s.time = time_of(doc, s.p);
    // mu sets the slip's relaxation (mu eps); dimensionless.mu (project extension), else
    // friction.mu, else 1 (said in the summary).
    const bool in_block = doc.at("dimensionless").contains("mu");
    if (!in_block && c.friction && c.friction->law == "coulomb") s.p.mu = c.friction->mu;
    s.mu_given = in_block || (c.friction && c.friction->law == "coulomb");
    s.units.mu = s.mu_given ? s.p.mu : 0.0;
  } else {
    s.p = dimensional_parameters(c, doc, s.units, s.time.dt);
    s.mu_given = true;
    s.time.scheme = scheme_of(doc);
  }
  pc::check(s.p);
  return s;
}

/// The creep law F/(mu P) of s computed by the tangential solver: steady rolling of a 2-D
/// cylinder (the case's materials, profile radius, normal force, friction and grid.nx when
/// given; steel, R = 0.05 m, 1e5 N/m, mu = 0.3, 200 strips otherwise) at creepage
/// xi = s mu a / R, tabulated on |s| <= 1 and interpolated linearly.
pc::TractionLaw numerical_law(const Case& c, const json& doc) {
  const MaterialPair m = doc.contains("materials") ? c.materials
                                                   : MaterialPair{Elastic::from_E_nu(2.1e11, 0.3),
                                                                  Elastic::from_E_nu(2.1e11, 0.3)};
  const double R = doc.contains("profile") && c.profile.radius > 0.0 ? c.profile.radius : 0.05;
  const double P = doc.contains("normal") && c.normal.control == Control::force ? c.normal.value : 1e5;
  const double mu = c.friction && c.friction->law == "coulomb" ? c.friction->mu : 0.3;
  const int nx = doc.contains("grid") && doc["grid"].contains("nx") ? c.grid.nx : 200;
  const auto hz = hertz::cylinder2d(R, P, m.E_star());
  const Grid g = Grid::make(2, nx, 1, -1.2 * hz.a, 1.2 * hz.a, 0, 0);
  ProfileSpec prof;
  prof.type = ProfileType::cylinder;
  prof.radius = R;
  TangentialProblem problem(g, m, profile_heights(prof, g), FrictionLaw::coulomb(mu));
  SolverSpec solver = c.solver;
  solver.backend = "native";
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

/// One sweep value (or none): the document with it applied, and its case.
struct RunSpec {
  std::string label;  ///< e.g. "gamma_bar = 0.5" (empty without a sweep)
  json value;
  json doc;
};

std::vector<RunSpec> sweep_runs(const json& doc) {
  if (!doc.contains("sweep")) return {{"", json(), doc}};
  const json& sw = doc.at("sweep");
  if (sw.size() != 1) throw InputError("sweep", "give exactly one key to sweep, e.g. {\"dimensionless.gamma_bar\": [...]}");
  const std::string key = sw.begin().key();
  const json& values = sw.begin().value();
  if (!values.is_array() || values.empty()) throw InputError("sweep." + key, "must be a non-empty array of values");
  const bool dimensionless = doc.contains("dimensionless") || !doc.contains("body");
  if (dimensionless && key.rfind("dimensionless.", 0) != 0)
    throw InputError("sweep." + key, "with dimensionless inputs, sweep a dimensionless.* key");
  std::vector<RunSpec> runs;
  for (const json& v : values) {
    RunSpec r;
    r.doc = doc;
    r.doc.erase("sweep");
    apply_override(r.doc, key + "=" + v.dump());
    r.value = v;
    const std::string shown = dimensionless ? key.substr(std::string("dimensionless.").size()) : key;
    r.label = shown + " = " + (v.is_string() ? v.get<std::string>() : v.dump());
    runs.push_back(std::move(r));
  }
  return runs;
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
void write_timeseries(const std::string& path, const pc::Run& run, const pc::Parameters& p, const Units& u,
                      const pc::TractionLaw& law) {
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
  write_text_file(path, out.str());
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
  (void)setup_of(c, c.source);
  for (const RunSpec& r : sweep_runs(c.source)) (void)setup_of(build_case(r.doc), r.doc);
}

int run_paper_cylinder(const Case& c, const std::string& dir, bool quiet) {
  validate_paper_cylinder(c);
  const json& doc = c.source;
  const std::string model = doc.value("traction_model", std::string("carter_poritsky"));
  const std::vector<RunSpec> specs = sweep_runs(doc);
  const Setup first = setup_of(c, doc);

  namespace fs = std::filesystem;
  json summary = {{"name", c.name},
                  {"problem", "paper_cylinder"},
                  {"traction_model", model},
                  {"inputs", first.units.dimensional ? "dimensional" : "dimensionless"},
                  {"scheme", first.time.scheme == pc::Scheme::bdf2 ? "bdf2" : "bdf1"}};
  json runs = json::array();
  std::vector<std::string> files, labels;
  bool all_ok = true;
  for (std::size_t k = 0; k < specs.size(); ++k) {
    const Case run_case = build_case(specs[k].doc);
    const Setup setup = setup_of(run_case, specs[k].doc);
    const pc::Parameters& p = setup.p;
    const pc::TractionLaw law = model == "numerical" ? numerical_law(run_case, specs[k].doc) : pc::TractionLaw{};
    const pc::Run run = pc::simulate(p, setup.time.dt, setup.time.scheme, law);
    const std::string file = specs.size() == 1 ? "timeseries.csv" : "timeseries_" + std::to_string(k) + ".csv";
    write_timeseries((fs::path(dir) / file).string(), run, p, setup.units, law);
    double onset = -1.0;
    for (const pc::Sample& s : run.samples)
      if (s.sliding) {
        onset = s.t_bar;
        break;
      }
    const pc::Sample q = pc::quasi_static(p, run.samples.back().t_bar);
    json r = {{"label", specs[k].label}, {"value", specs[k].value}, {"status", run.ok ? "completed" : "stopped"},
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
    runs.push_back(r);
    files.push_back(file);
    labels.push_back(specs[k].label.empty() ? c.name : specs[k].label);
    all_ok = all_ok && run.ok;
    if (!quiet) {
      const pc::Sample& s = run.samples.back();
      std::printf("%s%s%s: t_bar %.4g, F_bar %.5f, l_bar %.5f, v_bar %.5g%s%s\n", c.name.c_str(),
                  specs[k].label.empty() ? "" : " ", specs[k].label.c_str(), s.t_bar, s.F_bar, s.l_bar, s.v_bar,
                  onset >= 0.0 ? (", gross sliding from t_bar " + fmt(onset)).c_str() : "",
                  run.ok ? "" : (" [stopped: " + run.message + "]").c_str());
    }
  }
  summary["steps"] = runs[0]["steps"];
  summary["final"] = runs[0]["final"];
  summary["timeseries"] = files[0];
  summary["status"] = all_ok ? "completed" : "stopped";
  if (specs.size() > 1 || !specs[0].label.empty()) summary["runs"] = runs;
  else summary["run"] = runs[0];
  json out_files = {{"summary", "summary.json"}, {"timeseries", files}};

  if (c.output.plots) {
    std::vector<GnuplotFigure> figures;
    const char* names[][3] = {{"F_bar", "20", "friction force |F|/({/Symbol m}P)"},
                              {"l_bar", "21", "adhesion half-length 1 - d/l"},
                              {"v_bar", "22", "rigid-slip velocity |v|/({/Symbol m}{/Symbol e}V(0))"}};
    for (const auto& n : names) {
      std::ostringstream b;
      b << "set datafile separator \",\"\nset key top left noenhanced\nset grid\n"
        << "set xlabel \"time  t {/Symbol m}P / (M V(0))\"\nset yrange [0:*]\nset ylabel \"" << n[2] << "\"\n"
        << "set title \"" << c.name << "\" noenhanced\nplot ";
      for (std::size_t k = 0; k < files.size(); ++k)
        b << (k ? ", " : "") << "\"" << files[k] << "\" using 19:" << n[1] << " skip 1 with lines lw 2 title \""
          << labels[k] << "\"";
      b << "\n";
      figures.push_back({n[0], b.str()});
    }
    json plots = json::array();
    for (const auto& img : render_gnuplot(dir, c.name, figures)) plots.push_back(fs::path(img).filename().string());
    out_files["plots"] = plots;
  }
  summary["files"] = out_files;
  const std::string path = write_summary(dir, summary);
  if (!quiet) std::printf("wrote %s\n", path.c_str());
  if (!all_ok) {
    std::cerr << "error: a run stopped early (see " << path << ")\n";
    return kExitUnconverged;
  }
  return kExitOk;
}

}  // namespace dc::cli
