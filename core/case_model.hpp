#pragma once
// The case file contract (docs: shared spec CASES.md): JSON in, validated C++ values out.
// Every bad input throws InputError naming the key path and the reason.
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "grid.hpp"
#include "material.hpp"
#include "profile.hpp"

namespace dc {

enum class ProblemKind { normal, tangential, dynamic, paper_cylinder, finite };
enum class Control { force, approach };

struct NormalSpec {
  Control control = Control::force;
  double value = 0.0;  ///< force (N; 2-D N/m) or approach (m)
};

struct FrictionSpec {
  std::string law = "coulomb";  ///< coulomb | tresca | table
  double mu = 0.0;
  double bound = 0.0;                      ///< tresca
  std::vector<double> pressure, bound_table;  ///< table
};

struct SolverSpec {
  std::string backend = "auto";  ///< auto | ipopt | nlopt | native
  double tol = 1e-9;             ///< backend tolerance
  double certificate_tol = 1e-6; ///< largest accepted certificate residual
  int max_iter = 1000;
  bool fallback = true;          ///< auto: try the next backend when one fails
  bool accept_unconverged = false;  ///< write results (exit 0) even when the certificate fails
  std::string hessian = "auto";  ///< ipopt: exact | limited-memory | auto
  std::string operator_kind = "auto";  ///< auto | dense | fft
};

struct OutputSpec {
  std::string dir;       ///< empty: out/<name>
  bool fields = true;
  bool plots = true;
};

struct Case {
  std::string schema = "dyncontact/1";
  std::string name;
  ProblemKind problem = ProblemKind::normal;
  int dimension = 3;
  MaterialPair materials;
  ProfileSpec profile;
  Grid grid;
  NormalSpec normal;
  std::optional<FrictionSpec> friction;
  nlohmann::json tangential;  ///< tangential block, validated by the tangential problem
  SolverSpec solver;
  OutputSpec output;
  nlohmann::json source;      ///< the (overridden) JSON the case was read from
};

/// Parses JSON text; `origin` (file name) is used in messages, malformed JSON reports its line.
nlohmann::json parse_case_text(const std::string& text, const std::string& origin);
/// Reads a file (relative table paths are resolved against its folder).
nlohmann::json read_case_file(const std::string& path);
/// Applies one `--set path=value` override (value parsed as JSON, else taken as a string).
void apply_override(nlohmann::json& document, const std::string& assignment);
/// Validates and converts; `base_dir` resolves relative file names (profile tables).
Case build_case(const nlohmann::json& document, const std::string& base_dir = ".");

const char* to_string(ProblemKind kind);

}  // namespace dc
