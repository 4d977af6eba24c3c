#include "gnuplot_figures.hpp"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "cli_common.hpp"

namespace dc::cli {
namespace {

bool g_warned_missing = false;

/// Starts `gnuplot -e "terminal_set='<set>'" plots.gp` in `dir` (the script draws that set of
/// images only), its output appended to dir/plots.log. Returns the child's pid (-1: no fork).
pid_t start_gnuplot(const std::string& dir, const std::string& set) {
  std::cout.flush();
  std::cerr.flush();
  const std::string select = "terminal_set='" + set + "'";
  const pid_t pid = fork();
  if (pid != 0) return pid;
  if (chdir(dir.c_str()) != 0) _exit(126);
  const int fd = open("plots.log", O_WRONLY | O_CREAT | O_APPEND, 0644);
  if (fd >= 0) {
    dup2(fd, STDOUT_FILENO);
    dup2(fd, STDERR_FILENO);
    close(fd);
  }
  const int null_in = open("/dev/null", O_RDONLY);
  if (null_in >= 0) dup2(null_in, STDIN_FILENO);
  execlp("gnuplot", "gnuplot", "-e", select.c_str(), "plots.gp", static_cast<char*>(nullptr));
  _exit(127);
}

/// Waits for a child started by start_gnuplot; its exit status (127: gnuplot could not be started).
int wait_gnuplot(pid_t pid) {
  if (pid < 0) return 127;
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return 127;
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128;
}

}  // namespace

std::vector<std::string> render_gnuplot(const std::string& dir, const std::string& case_name,
                                        const std::vector<GnuplotFigure>& figures) {
  namespace fs = std::filesystem;
  auto path = [&](const std::string& name) { return (fs::path(dir) / name).string(); };
  std::ostringstream gp;
  gp << "# dyncontact plots of case '" << case_name << "'. Re-run here with: gnuplot plots.gp\n"
     << "png_term = (strstrt(GPVAL_TERMINALS, \"pngcairo\") > 0) ? \"pngcairo size 900,650 enhanced\" : "
        "\"png size 900,650\"\n";
  std::vector<std::string> images;
  // Both sets by default; the program draws them in two gnuplot processes at once (gnuplot -e
  // "terminal_set='svg'" plots.gp), which halves the plots' wall time on two cores.
  gp << "if (!exists(\"terminal_set\")) terminal_set = \"all\"\n";
  for (const std::string ext : {"svg", "png"}) {
    gp << "\n# ---- " << ext << "\n"
       << "if (terminal_set eq \"all\" || terminal_set eq \"" << ext << "\") {\n"
       << (ext == "svg" ? "set terminal svg size 900,650 enhanced\n" : "eval \"set terminal \".png_term\n");
    for (const auto& fig : figures) {
      gp << "reset\nset datafile missing \"?\"\nset output \"" << fig.stem << "." << ext << "\"\n"
         << fig.body << "unset output\n";
      images.push_back(path(fig.stem + "." + ext));
    }
    gp << "}\n";
  }
  write_text_file(path("plots.gp"), gp.str());
  write_text_file(path("plots.log"), "");

  const pid_t svg = start_gnuplot(dir, "svg"), png = start_gnuplot(dir, "png");
  const int svg_status = wait_gnuplot(svg), png_status = wait_gnuplot(png);
  // 127 (no gnuplot) only when neither could start; one failed fork is a failure of its set.
  const int status = svg_status == 127 && png_status == 127 ? 127 : svg_status != 0 ? svg_status : png_status;
  if (status == 127) {
    if (!g_warned_missing)
      std::cerr << "warning: gnuplot not found: no plots (the script and data are in " << dir << "/plots.gp)\n";
    g_warned_missing = true;
    return {};
  }
  if (status != 0) {
    std::cerr << "warning: gnuplot failed (exit " << status << "); see " << path("plots.log") << "\n";
    return {};
  }
  std::vector<std::string> produced;
  for (const auto& img : images)
    if (fs::exists(img)) produced.push_back(img);
  return produced;
}

}  // namespace dc::cli
