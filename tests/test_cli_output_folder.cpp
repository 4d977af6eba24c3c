// The output folder under concurrency, a full disk and kills: one run per folder (a second one
// refused at once, exit 2 naming the folder and its key), files whole or absent (a write that
// fails is exit 5 naming the file, summary.json is written last), and no temporaries left by a
// run killed while writing once the next run has started.
#include <gtest/gtest.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"

namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;
using Clock = std::chrono::steady_clock;
using dc::test::CliResult;
using dc::test::shell_quote;
using dc::test::slurp;

class CliOutputFolder : public dc::test::CliTest {
 protected:
  /// hertz-sphere on an nx x nx grid, plots off unless asked for.
  std::string hertz_case(int nx, bool plots = false, const std::string& name = "case.json") const {
    json doc = dc::test::example_json("hertz-sphere");
    doc["grid"] = {{"nx", nx}, {"ny", nx}, {"extent", 1.5}};
    doc["output"] = {{"plots", plots}};
    return write_case(doc, name);
  }

  /// Starts `dyncontact ARGS` in the test folder (output to run_<tag>.out/.err); returns its pid.
  pid_t start(const std::vector<std::string>& args, const std::string& tag) const {
    return CliTest::start(args, "run_" + tag + ".out", "run_" + tag + ".err");
  }

  /// Waits (at most 60 s) until `pid` holds the lock of `folder` (it writes its pid into the lock
  /// file once locked); false when it ended first.
  bool wait_for_lock(pid_t pid, const fs::path& folder) const {
    const auto begin = Clock::now();
    while (Clock::now() - begin < std::chrono::seconds(60)) {
      if (slurp(folder / ".dyncontact.lock") == std::to_string(pid) + "\n") return true;
      int status = 0;
      if (waitpid(pid, &status, WNOHANG) == pid) return false;
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    return false;
  }

  /// The temporaries (.partial-*) in `folder`.
  static std::vector<std::string> partials(const fs::path& folder) {
    std::vector<std::string> found;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(folder, ec)) {
      const std::string name = e.path().filename().string();
      if (name.rfind(".partial-", 0) == 0) found.push_back(name);
    }
    return found;
  }

  /// summary.json of `folder` is absent, or complete (parses) - never cut.
  static void expect_summary_absent_or_whole(const fs::path& folder) {
    const fs::path summary = folder / "summary.json";
    if (!fs::exists(summary)) return;
    EXPECT_TRUE(json::accept(slurp(summary))) << "a cut summary.json: " << slurp(summary);
  }

  /// The data rows of a CSV file (its lines after the header).
  static std::size_t csv_rows(const fs::path& file) {
    const std::string text = slurp(file);
    std::size_t lines = 0;
    for (char ch : text) lines += ch == '\n';
    return lines > 0 ? lines - 1 : 0;
  }
};

TEST_F(CliOutputFolder, SecondRunIntoALockedFolderIsRefusedAtOnceAndTheFirstOneCompletes) {
  const std::string big = hertz_case(192, false, "big.json"), small = hertz_case(16, false, "small.json");
  const fs::path out = dir_ / "out";
  // The first run is held (SIGSTOP) once it has locked the folder, so the second one surely
  // meets it whatever the machine's load.
  const pid_t first = start({"solve", big, "--out", "out", "-q"}, "first");
  ASSERT_TRUE(wait_for_lock(first, out)) << "the first run ended before it locked the folder: "
                                         << slurp(dir_ / "run_first.err");
  kill(first, SIGSTOP);
  // At once: the second run ends while the first one, held, still holds the folder.
  const CliResult second = run("solve " + small + " --out out -q");
  kill(first, SIGCONT);
  EXPECT_EQ(second.code, 2) << second.err;
  EXPECT_NE(second.err.find("error: --out:"), std::string::npos) << second.err;
  EXPECT_NE(second.err.find("'out'"), std::string::npos) << "the message names the folder: " << second.err;
  EXPECT_NE(second.err.find("in use"), std::string::npos) << second.err;
  EXPECT_EQ(wait_exit(first), 0) << slurp(dir_ / "run_first.err");

  // The folder holds the first run's files only: summary and fields of one 192 x 192 run.
  const json summary = json::parse(slurp(out / "summary.json"));
  EXPECT_EQ(summary["grid"]["nx"], 192);
  EXPECT_EQ(csv_rows(out / "fields.csv"), summary["grid"]["elements"].get<std::size_t>());
  EXPECT_TRUE(partials(out).empty());

  // The lock went with the first run: a run after it is not refused.
  const CliResult again = run("solve " + small + " --out out -q");
  EXPECT_EQ(again.code, 0) << again.err;
  EXPECT_EQ(json::parse(slurp(out / "summary.json"))["grid"]["nx"], 16);
  EXPECT_EQ(csv_rows(out / "fields.csv"), 16u * 16u);
}

TEST_F(CliOutputFolder, EveryRunKindAndKeyIsRefusedWhileAnotherProcessHoldsTheFolder) {
  const fs::path out = dir_ / "held";
  fs::create_directories(out);
  const int fd = open((out / ".dyncontact.lock").c_str(), O_RDWR | O_CREAT, 0644);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(flock(fd, LOCK_EX | LOCK_NB), 0);
  // A file of an earlier run that a refused run must leave alone.
  const fs::path earlier = out / "summary.json";
  { std::ofstream(earlier) << "{\"earlier\": true}\n"; }
  const std::string c = hertz_case(16);
  for (const std::string& command :
       {"solve " + c + " --out held", "compare " + c + " --backends native,ipopt --out held",
        "solve " + shell_quote(dc::test::example_path("ball-impact")) + " --out held",
        "solve " + shell_quote(dc::test::example_path("ball-impact-speeds")) + " --out held",
        "solve " + shell_quote(dc::test::example_path("paper-cylinder")) + " --out held",
        "table " + shell_quote(dc::test::example_path("rolling-sphere")) + " --creepage 0,0.001 --out held"}) {
    const CliResult r = run(command + " -q");
    EXPECT_EQ(r.code, 2) << command << "\n" << r.err;
    EXPECT_NE(r.err.find("error: --out: the output folder 'held' is in use"), std::string::npos)
        << command << "\n" << r.err;
  }
  // The key is the one that chose the folder: output.dir from the case.
  json doc = dc::test::example_json("hertz-sphere");
  doc["output"] = {{"dir", "held"}};
  expect_input_error("solve " + write_case(doc, "with_dir.json") + " -q", "output.dir");
  EXPECT_EQ(slurp(earlier), "{\"earlier\": true}\n") << "a refused run removed an earlier result";
  close(fd);
  const CliResult after = run("solve " + c + " --out held -q");
  EXPECT_EQ(after.code, 0) << after.err;
}

TEST_F(CliOutputFolder, AFileSizeLimitIsExit5NamingTheFileWithNoCutSummary) {
  // sh's ulimit -f counts 512-byte blocks. 20 blocks (10 kB): fields.csv of 64 x 64 elements
  // (about 200 kB) fails; summary.json, written last, is never started.
  const std::string c = hertz_case(64);
  const CliResult fields = run_prefixed("ulimit -f 20;", "solve " + c + " --out out -q");
  EXPECT_EQ(fields.code, 5) << fields.err;
  EXPECT_NE(fields.err.find("out/fields.csv"), std::string::npos) << fields.err;
  EXPECT_NE(fields.err.find("File too large"), std::string::npos) << fields.err;
  EXPECT_FALSE(fs::exists(dir_ / "out" / "summary.json"));
  EXPECT_FALSE(fs::exists(dir_ / "out" / "fields.csv")) << "a cut fields.csv under its own name";
  EXPECT_TRUE(partials(dir_ / "out").empty());

  // 2 blocks (1 kB): no fields, and the summary itself (about 3 kB) does not fit.
  json doc = json::parse(slurp(dir_ / c));
  doc["output"]["fields"] = false;
  const std::string no_fields = write_case(doc, "no_fields.json");
  const CliResult summary = run_prefixed("ulimit -f 2;", "solve " + no_fields + " --out out -q");
  EXPECT_EQ(summary.code, 5) << summary.err;
  EXPECT_NE(summary.err.find("out/summary.json"), std::string::npos) << summary.err;
  EXPECT_FALSE(fs::exists(dir_ / "out" / "summary.json")) << "a cut summary.json";
  EXPECT_TRUE(partials(dir_ / "out").empty());

  // Without the limit the same folder takes a whole run.
  const CliResult whole = run("solve " + c + " --out out -q");
  EXPECT_EQ(whole.code, 0) << whole.err;
  EXPECT_EQ(json::parse(slurp(dir_ / "out" / "summary.json"))["grid"]["nx"], 64);
  EXPECT_TRUE(partials(dir_ / "out").empty());
}

TEST_F(CliOutputFolder, AFigureGnuplotCouldNotFinishIsExit5AndNotReported) {
  if (std::system("gnuplot --version >/dev/null 2>&1") != 0) GTEST_SKIP() << "no gnuplot";
  // 50 blocks (25 kB): the data files of a 12 x 12 grid fit, the figures (about 40 kB an SVG)
  // do not; gnuplot itself exits 0 with cut images.
  const std::string c = hertz_case(12, true);
  const CliResult r = run_prefixed("ulimit -f 50;", "solve " + c + " --out out");
  EXPECT_EQ(r.code, 5) << r.err;
  EXPECT_NE(r.err.find("out/pressure_x."), std::string::npos) << r.err;
  EXPECT_EQ(r.out.find("wrote"), std::string::npos) << "reported as written: " << r.out;
  EXPECT_FALSE(fs::exists(dir_ / "out" / "summary.json"));
  for (const char* image : {"pressure_x.svg", "pressure_x.png", "contact_map.svg", "contact_map.png"})
    EXPECT_FALSE(fs::exists(dir_ / "out" / image)) << image;
  EXPECT_TRUE(partials(dir_ / "out").empty());
}

TEST_F(CliOutputFolder, ARunKilledWhileWritingLeavesNoTemporariesAfterTheNextRun) {
  // A dynamic run writing a 96 x 96 fields_<k>.csv (about 0.4 MB) every step: held now and then
  // until it is caught with a temporary in the folder, then killed there.
  json doc = dc::test::example_json("ball-impact");
  doc["grid"]["nx"] = 96;
  doc["grid"]["ny"] = 96;
  doc["output"] = {{"plots", false}, {"snapshot_every", 1}};
  const std::string c = write_case(doc);
  const fs::path out = dir_ / "out";
  const pid_t pid = start({"solve", c, "--out", "out", "-q"}, "killed");
  ASSERT_TRUE(wait_for_lock(pid, out)) << slurp(dir_ / "run_killed.err");
  bool caught = false;
  const auto begin = Clock::now();
  while (!caught && Clock::now() - begin < std::chrono::seconds(60)) {
    int status = 0;
    if (waitpid(pid, &status, WNOHANG) == pid) break;
    kill(pid, SIGSTOP);
    caught = !partials(out).empty();
    if (caught) {
      kill(pid, SIGKILL);
    } else {
      kill(pid, SIGCONT);
      std::this_thread::sleep_for(std::chrono::microseconds(500));
    }
  }
  if (!caught) {
    ADD_FAILURE() << "the run was never caught writing a file: " << slurp(dir_ / "run_killed.err");
    kill(pid, SIGKILL);
  }
  EXPECT_EQ(wait_exit(pid), 128 + SIGKILL);
  ASSERT_TRUE(caught);
  EXPECT_FALSE(partials(out).empty());
  expect_summary_absent_or_whole(out);

  // The next run into the folder clears the temporaries (and its lock was not left held).
  doc["grid"]["nx"] = 16;
  doc["grid"]["ny"] = 16;
  doc["output"]["snapshot_every"] = 0;
  const CliResult r = run("solve " + write_case(doc, "small.json") + " --out out -q");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(partials(out).empty());
  EXPECT_TRUE(json::accept(slurp(out / "summary.json")));
}

TEST_F(CliOutputFolder, AnExampleThatCannotBeWrittenIsExit5) {
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  const fs::path err = dir_ / "stderr.txt";
  const int status = std::system((shell_quote(DYNCONTACT_BINARY) + " example hertz-sphere >/dev/full 2>" +
                                  shell_quote(err.string()))
                                     .c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 5) << slurp(err);
  EXPECT_NE(slurp(err).find("standard output"), std::string::npos) << slurp(err);
  EXPECT_NE(slurp(err).find("No space left on device"), std::string::npos) << slurp(err);
}

}  // namespace
