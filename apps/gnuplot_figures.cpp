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

/// Runs `gnuplot plots.gp` in `dir`, its output going to dir/plots.log. Returns the exit
/// status (127: gnuplot could not be started).
int run_gnuplot(const std::string& dir) {
  std::cout.flush();
  std::cerr.flush();
  const pid_t pid = fork();
  if (pid < 0) return 127;
  if (pid == 0) {
    if (chdir(dir.c_str()) != 0) _exit(126);
    const int fd = open("plots.log", O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) {
      dup2(fd, STDOUT_FILENO);
      dup2(fd, STDERR_FILENO);
      close(fd);
    }
    const int null_in = open("/dev/null", O_RDONLY);
    if (null_in >= 0) dup2(null_in, STDIN_FILENO);
    execlp("gnuplot", "gnuplot", "plots.gp", static_cast<char*>(nullptr));
    _exit(127);
  }
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
  for (const char* ext : {"svg", "png"}) {
    gp << "\n# ---- " << ext << "\n"
       << (std::string(ext) == "svg" ? "set terminal svg size 900,650 enhanced\n" : "eval \"set terminal \".png_term\n");
    for (const auto& fig : figures) {
      gp << "reset\nset datafile missing \"?\"\nset output \"" << fig.stem << "." << ext << "\"\n"
         << fig.body << "unset output\n";
      images.push_back(path(fig.stem + "." + ext));
    }
  }
  write_text_file(path("plots.gp"), gp.str());

  const int status = run_gnuplot(dir);
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
