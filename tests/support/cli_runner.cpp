#include "cli_runner.hpp"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace dc::test {

namespace fs = std::filesystem;

std::string example_path(const std::string& name) {
  return (fs::path(DYNCONTACT_SOURCE_DIR) / "examples" / (name + ".json")).string();
}

nlohmann::json example_json(const std::string& name) { return nlohmann::json::parse(slurp(example_path(name))); }

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

nlohmann::json coarse_ball_impact() {
  nlohmann::json doc = example_json("ball-impact");
  doc["grid"]["nx"] = doc["grid"]["ny"] = 12;
  doc["time"]["dt"] = 2e-6;
  doc["output"] = {{"plots", false}};
  return doc;
}

std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

pid_t CliTest::start(const std::vector<std::string>& args, const std::string& out, const std::string& err) const {
  const pid_t pid = fork();
  if (pid == 0) {
    if (chdir(dir_.c_str()) != 0) _exit(127);
    const int out_fd = open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err_fd = open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    dup2(out_fd, 1);
    dup2(err_fd, 2);
    std::vector<char*> argv{const_cast<char*>(program_)};
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    execv(program_, argv.data());
    _exit(127);
  }
  return pid;
}

int CliTest::wait_exit(pid_t pid) {
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

void CliTest::SetUp() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  dir_ = fs::temp_directory_path() /
         ("dc_cli_" + std::to_string(::getpid()) + "_" + info->test_suite_name() + "_" + info->name());
  fs::remove_all(dir_);
  fs::create_directories(dir_);
}

void CliTest::TearDown() {
  if (!HasFailure()) fs::remove_all(dir_);
}

CliResult CliTest::run(const std::string& args) const { return run_prefixed("", args); }

std::string CliTest::write_case(const nlohmann::json& doc, const std::string& name) const {
  std::ofstream(dir_ / name) << doc.dump(2);
  return name;
}

void CliTest::expect_input_error(const std::string& command, const std::string& key) const {
  const CliResult r = run(command);
  EXPECT_EQ(r.code, 2) << command << "\nstderr: " << r.err;
  EXPECT_NE(r.err.find("error: " + key + ":"), std::string::npos) << command << "\nstderr: " << r.err;
}

CliResult CliTest::run_mpi2(const std::string& args) const {
  // Under AddressSanitizer the ranks are not leak-checked: Open MPI keeps allocations to the end
  // of the process from plugins it has unloaded by then (no module name to suppress them by).
  // The same code runs leak-checked without mpirun in the other tests.
  return run_prefixed("OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1 "
                      "ASAN_OPTIONS=\"${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0\" mpirun -n 2 --oversubscribe",
                      args);
}

bool CliTest::have_mpirun() { return std::system("mpirun --version >/dev/null 2>&1") == 0; }

CliResult CliTest::run_prefixed(const std::string& prefix, const std::string& args) const {
  const fs::path out = dir_ / "stdout.txt", err = dir_ / "stderr.txt";
  const std::string cmd = "cd " + shell_quote(dir_.string()) + " && " + prefix + " " + shell_quote(program_) +
                          " " + args + " >" + shell_quote(out.string()) + " 2>" + shell_quote(err.string());
  const int status = std::system(cmd.c_str());
  CliResult r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
  r.out = slurp(out);
  r.err = slurp(err);
  return r;
}

}  // namespace dc::test
