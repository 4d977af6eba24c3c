// SIGTERM to a finite-element run while it meshes the body or factorises its stiffness (single
// calls that cannot poll the interrupt): the watchdog ends the process within a second (its
// grace is half a second), exit 143, with summary.json saying "interrupted"; and the size of a
// body beyond the machine's memory is refused before anything is meshed.
#include <gtest/gtest.h>
#include <signal.h>

#include <chrono>
#include <string>
#include <thread>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"

namespace dc::test {
namespace {

using nlohmann::json;
using Clock = std::chrono::steady_clock;

/// The promised stop within a second; a sanitizer build on a busy machine is given three.
constexpr double kStopSeconds = DYNCONTACT_SANITIZED ? 3.0 : 1.0;

using FiniteInterrupt = CliTest;

TEST_F(FiniteInterrupt, MeshingOrFactorisingStopsWithinASecondOfSigterm) {
  // 19k tetrahedra, 87k dofs: about 1 s of meshing and 15 s of factorisation uninterrupted.
  const std::string file = write_case(example_json("finite-hemisphere"));
  for (const double after : {0.3, 1.5}) {
    SCOPED_TRACE(after);
    const pid_t pid = start({"solve", file, "-q", "--out", "intr", "--set", "fe_body.elements=[24,24,12]"},
                            "stdout.txt", "stderr.txt");
    std::this_thread::sleep_for(std::chrono::duration<double>(after));
    const auto sent = Clock::now();
    kill(pid, SIGTERM);
    const int code = wait_exit(pid);
    const double seconds = std::chrono::duration<double>(Clock::now() - sent).count();
    EXPECT_EQ(code, 143) << slurp(dir_ / "stderr.txt");
    EXPECT_LT(seconds, kStopSeconds + 0.1) << slurp(dir_ / "stderr.txt");
    const json s = json::parse(slurp(dir_ / "intr" / "summary.json"));
    EXPECT_EQ(s["status"], "interrupted");
  }
}

TEST_F(FiniteInterrupt, ABodyBeyondTheMemoryIsRefusedBeforeMeshing) {
  // [300,300,150] divisions: about 3e7 tetrahedra, 1.5e8 dofs and 17 TB to factorise ([60,60,30],
  // 27 GB, is refused on a machine of 24 GB).
  const std::string file = write_case(example_json("finite-hemisphere"));
  const auto start = Clock::now();
  expect_input_error("validate " + file + " --set 'fe_body.elements=[300,300,150]'", "fe_body.elements");
  expect_input_error("solve " + file + " -q --set 'fe_body.elements=[300,300,150]'", "fe_body.elements");
  EXPECT_LT(std::chrono::duration<double>(Clock::now() - start).count(), 10.0);  // nothing meshed
  // A tiny contact element size: the refined zone holds the tetrahedra.
  expect_input_error("validate " + file + " --set fe_body.contact_size=2e-6", "fe_body.contact_size");
}

}  // namespace
}  // namespace dc::test
