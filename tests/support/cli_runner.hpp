#pragma once
// Runs the built `dyncontact` program from tests: a fresh folder per test, exit code and
// captured output.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

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
/// Single-quoted for the shell.
std::string shell_quote(const std::string& s);

/// Fixture: a temporary folder per test (kept when the test fails) and run().
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
  std::filesystem::path dir_;
};

}  // namespace dc::test
