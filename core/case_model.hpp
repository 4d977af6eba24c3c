#pragma once
// The case file contract (docs: shared spec CASES.md): JSON in, validated C++ values out.
// Every bad input throws InputError naming the key path and the reason.
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "case_fe_body.hpp"
#include "case_dynamic.hpp"
#include "case_paper_cylinder.hpp"
#include "case_tangential.hpp"
#include "grid.hpp"
#include "material.hpp"
#include "normal_spec.hpp"
#include "profile.hpp"
#include "solver_options.hpp"

namespace dc {

enum class ProblemKind { normal, tangential, dynamic, paper_cylinder, finite };

/// The friction bound f(p) (friction_law.hpp): "coulomb", "tresca" or "table" in the case file.
enum class FrictionLawKind { coulomb, tresca, table };

struct FrictionSpec {
  FrictionLawKind law = FrictionLawKind::coulomb;
  double mu = 0.0;
  double bound = 0.0;                      ///< tresca
  std::vector<double> pressure, bound_table;  ///< table
};

struct OutputSpec {
  std::string dir;       ///< empty: out/<name>
  bool fields = true;
  bool plots = true;
  int snapshot_every = 0;  ///< dynamic: the contact fields every k steps (0: none)
};

// Reading a block (the pattern every block follows; core/case_model.cpp):
//  - a typed spec `<Block>Spec` and `<Block>Spec read_<block>(const json&, ...)` in
//    core/case_<block>.{hpp,cpp}, reading only through JsonBlock (json_block.hpp): allow() the
//    keys, typed getters, InputError(key path, reason) for every bad value;
//  - the spec held here as std::optional<<Block>Spec> (set when the block was read);
//  - build_case() calls the reader, and kBlockUses (case_model.cpp) lists the problems that
//    use the block: in any other problem the block is an error naming it.
// Solvers (nlp/, dynamics/) and the command line take these specs, never JSON.
// Blocks still to come this way: none.

/// `sweep`: one run per value of one key of the case (paper_cylinder, dynamic).
struct SweepSpec {
  std::string key;        ///< the swept key's path, e.g. "loads.moment.y.rate"
  nlohmann::json values;  ///< a non-empty array, one run each
};

struct Case {
  std::string schema = "dyncontact/1";
  std::string name;
  std::string description;
  ProblemKind problem = ProblemKind::normal;
  int dimension = 3;
  MaterialPair materials;
  ProfileSpec profile;
  Grid grid;
  bool allow_edge_contact = false;  ///< grid.allow_edge_contact: a contact truncated by the grid edge is accepted
  bool allow_large_strain = false;  ///< materials.allow_large_strain: a contact as large as the body is accepted
  NormalSpec normal;
  std::optional<FrictionSpec> friction;
  std::optional<TangentialSpec> tangential;        ///< problem tangential
  std::optional<PaperCylinderSpec> paper_cylinder;  ///< problem paper_cylinder
  std::optional<FeBodySpec> fe_body;                ///< problem finite
  std::optional<DynamicSpec> dynamic;               ///< problem dynamic
  std::optional<SweepSpec> sweep;                   ///< problems paper_cylinder, dynamic
  SolverOptions solver;                             ///< the `solver` block (solver_options.hpp)
  OutputSpec output;
  std::vector<std::string> blocks;  ///< the top-level keys the case file gave
  nlohmann::json source;            ///< the (overridden) JSON the case was read from (sweeps re-read it)

  /// Whether the case file gave the top-level key `block`.
  bool has_block(const std::string& block) const;
};

/// One run of a sweep: its label ("gamma_bar = 0.5"), the swept value and its case.
struct SweepPoint {
  std::string label;  ///< empty without a sweep
  nlohmann::json value;
  Case run;
};

/// Reads the top-level `sweep` block (core/case_sweep.cpp).
SweepSpec read_sweep(const nlohmann::json& block);

/// The runs of a case's sweep, each its own validated case (its label "key = value", a
/// "dimensionless." prefix left out); without a sweep the case itself (core/case_sweep.cpp).
std::vector<SweepPoint> sweep_points(const Case& c);

/// Parses JSON text; `origin` (file name) is used in messages, malformed JSON reports its line.
nlohmann::json parse_case_text(const std::string& text, const std::string& origin);
/// Reads a file (relative table paths are resolved against its folder).
nlohmann::json read_case_file(const std::string& path);
/// Applies one `--set path=value` override (value parsed as JSON, else taken as a string).
void apply_override(nlohmann::json& document, const std::string& assignment);
/// Validates and converts; `base_dir` resolves relative file names (profile tables).
Case build_case(const nlohmann::json& document, const std::string& base_dir = ".");

const char* to_string(ProblemKind kind);
/// "coulomb", "tresca", "table".
const char* to_string(FrictionLawKind law);

}  // namespace dc
