#pragma once
// The case file contract (docs: shared spec CASES.md): JSON in, validated C++ values out. The
// case layer (apps/case/, dyncontact_case) sits above the solvers: it reads a case into the typed
// specs they take (ContactSpec, DynamicContactSpec, the tangential loads) and builds and solves
// their problems (solve_case.hpp). Every bad input throws InputError naming the key path and
// the reason.
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "accuracy_spec.hpp"
#include "subsurface_spec.hpp"
#include "dynamic_spec.hpp"
#include "paper_cylinder_spec.hpp"
#include "tangential_spec.hpp"
#include "wear_spec.hpp"
#include "thermal_spec.hpp"

namespace dc {

enum class ProblemKind { normal, tangential, dynamic, paper_cylinder, finite };

struct OutputSpec {
  std::string dir;       ///< empty: out/<name>
  bool fields = true;
  bool plots = true;
  int snapshot_every = 0;  ///< dynamic: the contact fields every k steps (0: none)
  /// fields.csv also the frictional power density (`power`, W/m^2) or the step's work per area
  /// (`dissipation`, J/m^2) as a last column; off: the contract's columns only.
  bool power = false;
};

// Reading a block (the pattern every block follows):
//  - a typed spec `<Block>Spec` in the layer that takes it (core/normal_spec.hpp, nlp/,
//    dynamics/dynamic_spec.hpp, or here when only the runs take it), declared without JSON;
//  - its reader `read_<block>(const json&, ...)` in apps/case/read_<block>.cpp, declared in
//    case_readers.hpp, reading only through JsonBlock (json_block.hpp): allow() the keys, typed
//    getters, InputError(key path, reason) for every bad value;
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

/// A case: the specs the solvers take (materials, profile, grid, normal, friction, fe_body,
/// solver: ContactSpec; dynamic: DynamicContactSpec), and what only the runs use.
struct Case : DynamicContactSpec {
  std::string schema = "dyncontact/1";
  std::string name;
  std::string description;
  ProblemKind problem = ProblemKind::normal;
  std::optional<TangentialSpec> tangential;        ///< problem tangential
  std::optional<PaperCylinderSpec> paper_cylinder;  ///< problem paper_cylinder
  std::optional<SweepSpec> sweep;                   ///< problems paper_cylinder, dynamic
  OutputSpec output;
  AccuracySpec accuracy;                            ///< problems normal, tangential
  SubsurfaceSpec subsurface;                        ///< problems normal, tangential (the final state)
  BodyYields yields;                                ///< materials.*.yield (problems normal, tangential)
  BodyFatigue fatigue;                              ///< materials.*.fatigue (problems normal, tangential)
  bool shakedown = false;                           ///< "shakedown": Melan's limit of the rolling load
  std::optional<WearSpec> wear;                     ///< "wear": a history's, steady rolling's or a dynamic run's worn depth
  ThermalSpec thermal;                              ///< materials.*.thermal, "temperature" (rolling: the flash temperature)
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

/// The runs of a case's sweep, each its own validated case (its label "key = value", a
/// "dimensionless." prefix left out); without a sweep the case itself (read_sweep.cpp).
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

}  // namespace dc
