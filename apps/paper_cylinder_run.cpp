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
                     "required: the paper's dimensionless inputs (the dimensional form with body/loads is not "
                     "implemented yet)");
  const json& d = doc.at("dimensionless");
  if (!d.is_object()) throw InputError("dimensionless", "expected an object");
  check_keys(d, "dimensionless", {"gamma_bar", "M0_bar", "eta", "epsilon", "v_bar0", "t_bar_end", "T_bar"});
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
  if (d.contains("eta")) {
    const json& e = d.at("eta");
    if (e.is_string() && e.get<std::string>() == "inf") p.eta = std::numeric_limits<double>::infinity();
    else p.eta = number(e, "dimensionless.eta");
  }
  return p;
}

struct TimeSpec {
  double dt = 0.0;
  pc::Scheme scheme = pc::Scheme::bdf1;
};

TimeSpec time_of(const json& doc, const pc::Parameters& p) {
  TimeSpec t;
  t.dt = p.t_bar_end / 1000.0;
  if (!doc.contains("time")) return t;
  const json& b = doc.at("time");
  check_keys(b, "time", {"dt", "scheme"});
  if (b.contains("dt")) t.dt = number(b.at("dt"), "time.dt");
  if (!(t.dt > 0.0)) throw InputError("time.dt", "must be positive (a step of t_bar for dimensionless inputs)");
  if (b.contains("scheme")) {
    const std::string s = b.at("scheme").is_string() ? b.at("scheme").get<std::string>() : "";
    if (s != "bdf1" && s != "bdf2") throw InputError("time.scheme", "must be \"bdf1\" or \"bdf2\"");
    t.scheme = s == "bdf2" ? pc::Scheme::bdf2 : pc::Scheme::bdf1;
  }
  return t;
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

/// One sweep value (or none): the document with it applied.
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
  if (key.rfind("dimensionless.", 0) != 0)
    throw InputError("sweep." + key, "paper_cylinder sweeps a dimensionless.* input");
  if (!values.is_array() || values.empty()) throw InputError("sweep." + key, "must be a non-empty array of values");
  std::vector<RunSpec> runs;
  for (const json& v : values) {
    RunSpec r;
    r.doc = doc;
    r.doc["dimensionless"][key.substr(std::string("dimensionless.").size())] = v;
    r.value = v;
    r.label = key.substr(std::string("dimensionless.").size()) + " = " + (v.is_string() ? v.get<std::string>() : v.dump());
    runs.push_back(std::move(r));
  }
  return runs;
}

std::string fmt(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.9g", v);
  return b;
}

/// timeseries.csv of the contract in the paper's units (t in M V0/(mu P), x in M V0^2/(mu P),
/// velocities in V0, forces in mu P, moments in mu P R); the columns that need mu itself
/// (omega, F_z, creepage) are left empty unless the case gives friction.mu.
void write_timeseries(const std::string& path, const pc::Run& run, const pc::Parameters& p, double mu,
                      const pc::TractionLaw& law) {
  std::ostringstream out;
  out << "t,x,y,z,vx,vy,vz,wx,wy,wz,Fx,Fy,Fz,Mx,My,Mz,creepage,stick_fraction,t_bar,F_bar,l_bar,v_bar\n";
  const bool has_mu = mu > 0.0;
  double x = 0.0;
  for (std::size_t k = 0; k < run.samples.size(); ++k) {
    const pc::Sample& s = run.samples[k];
    if (k > 0) x += 0.5 * (s.u + run.samples[k - 1].u) * (s.t_bar - run.samples[k - 1].t_bar);
    const double ratio = s.w / s.u;
    out << fmt(s.t_bar) << ',' << fmt(x) << ",0,0," << fmt(s.u) << ",0,0,0,"
        << (has_mu ? fmt(s.u - mu * p.epsilon * s.w) : "") << ",0," << fmt(-law.force_ratio(ratio)) << ",0,"
        << (has_mu ? fmt(1.0 / mu) : "") << ",0," << fmt(p.M0_bar + p.gamma_bar * s.t_bar) << ",0,"
        << (has_mu ? fmt(mu * p.epsilon * ratio) : "") << ',' << fmt(s.l_bar) << ',' << fmt(s.t_bar) << ','
        << fmt(s.F_bar) << ',' << fmt(s.l_bar) << ',' << fmt(s.v_bar) << '\n';
  }
  write_text_file(path, out.str());
}

json final_of(const pc::Run& run) {
  const pc::Sample& s = run.samples.back();
  double x = 0.0;
  for (std::size_t k = 1; k < run.samples.size(); ++k)
    x += 0.5 * (run.samples[k].u + run.samples[k - 1].u) * (run.samples[k].t_bar - run.samples[k - 1].t_bar);
  return {{"time", s.t_bar}, {"position", {x, 0.0, 0.0}}, {"velocity", {s.u, 0.0, 0.0}}, {"omega", nullptr},
          {"t_bar", s.t_bar}, {"F_bar", s.F_bar}, {"l_bar", s.l_bar}, {"v_bar", s.v_bar}, {"sliding", s.sliding}};
}

}  // namespace

void validate_paper_cylinder(const Case& c) {
  const pc::Parameters base = parameters_of(c.source);
  pc::check(base);
  (void)time_of(c.source, base);
  for (const RunSpec& r : sweep_runs(c.source)) pc::check(parameters_of(r.doc));
}

int run_paper_cylinder(const Case& c, const std::string& dir, bool quiet) {
  validate_paper_cylinder(c);
  const json& doc = c.source;
  const pc::Parameters base = parameters_of(doc);
  const TimeSpec time = time_of(doc, base);
  const std::string model = doc.value("traction_model", std::string("carter_poritsky"));
  const double mu = c.friction && c.friction->law == "coulomb" ? c.friction->mu : 0.0;
  const pc::TractionLaw law = model == "numerical" ? numerical_law(c, doc) : pc::TractionLaw{};
  const std::vector<RunSpec> specs = sweep_runs(doc);

  namespace fs = std::filesystem;
  json summary = {{"name", c.name}, {"problem", "paper_cylinder"}, {"traction_model", model},
                  {"scheme", time.scheme == pc::Scheme::bdf2 ? "bdf2" : "bdf1"}, {"dt_bar", time.dt}};
  json runs = json::array();
  std::vector<std::string> files, labels;
  bool all_ok = true;
  for (std::size_t k = 0; k < specs.size(); ++k) {
    const pc::Parameters p = parameters_of(specs[k].doc);
    const pc::Run run = pc::simulate(p, time.dt, time.scheme, law);
    const std::string file = specs.size() == 1 ? "timeseries.csv" : "timeseries_" + std::to_string(k) + ".csv";
    write_timeseries((fs::path(dir) / file).string(), run, p, mu, law);
    double onset = -1.0;
    for (const pc::Sample& s : run.samples)
      if (s.sliding) {
        onset = s.t_bar;
        break;
      }
    const pc::Sample q = pc::quasi_static(p, run.samples.back().t_bar);
    json r = {{"label", specs[k].label}, {"value", specs[k].value}, {"status", run.ok ? "completed" : "stopped"},
              {"message", run.message}, {"steps", static_cast<int>(run.samples.size()) - 1},
              {"final", final_of(run)}, {"timeseries", file},
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
