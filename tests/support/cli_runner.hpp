#pragma once
// Runs the built `dyncontact` program from tests: a fresh folder per test, exit code and
// captured output.
#include <gtest/gtest.h>
#include <sys/types.h>

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace dc::test {

struct CliResult {
  int code = -1;
  std::string out, err;
};

/// The whole file as a string (empty when missing).
std::string slurp(const std::filesystem::path& p);
/// The bundled example examples/NAME.json, parsed.
nlohmann::json example_json(const std::string& name);
/// Its path.
std::string example_path(const std::string& name);
/// The ball-impact example on 12 x 12 elements with dt 2e-6 s (40 steps, 34 per Hertz contact
/// time), plots off: a dynamic run of a fraction of a second.
nlohmann::json coarse_ball_impact();
/// Single-quoted for the shell.
std::string shell_quote(const std::string& s);

/// Fixture: a temporary folder per test (kept when the test fails) and run(), which runs the
/// built `dyncontact`.
class CliTest : public ::testing::Test {
 protected:
  void SetUp() override;
  void TearDown() override;
  /// Runs `dyncontact ARGS` (ARGS already shell-quoted) in the test folder.
  CliResult run(const std::string& args) const;
  /// Runs `PREFIX dyncontact ARGS`: PREFIX holds environment assignments or a launcher
  /// (e.g. "DYNCONTACT_THREADS=1", "mpirun -n 2").
  CliResult run_prefixed(const std::string& prefix, const std::string& args) const;
  /// Writes DOC into the test folder as NAME; returns NAME.
  std::string write_case(const nlohmann::json& doc, const std::string& name = "case.json") const;
  /// COMMAND (e.g. "validate case.json") exits 2 and says "error: KEY:" on stderr.
  void expect_input_error(const std::string& command, const std::string& key) const;
  /// Starts `dyncontact ARGS` in the test folder without waiting, stdout and stderr into the
  /// files `out` and `err` there; returns its pid.
  pid_t start(const std::vector<std::string>& args, const std::string& out, const std::string& err) const;
  /// Waits for `pid`; its exit code, 128 + the signal when a signal ended it.
  static int wait_exit(pid_t pid);
  /// `mpirun -n 2 --oversubscribe dyncontact ARGS` (allowed as root too).
  CliResult run_mpi2(const std::string& args) const;
  /// Whether `mpirun` is on PATH.
  static bool have_mpirun();
  /// From here on, run the test-only program that injects the faults DYNCONTACT_FAULT names
  /// (support/program_with_faults.cpp) instead of `dyncontact`.
  void use_program_with_faults() { program_ = DYNCONTACT_PROGRAM_WITH_FAULTS; }
  std::filesystem::path dir_;
  const char* program_ = DYNCONTACT_BINARY;
};

}  // namespace dc::test
