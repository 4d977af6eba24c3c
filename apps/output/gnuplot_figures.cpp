#include "gnuplot_figures.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>
#ifdef __linux__
#include <sys/prctl.h>
#endif

#include <algorithm>
#include <cmath>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "interrupt_signals.hpp"
#include "output_files.hpp"

namespace dc::output {
namespace {

// Said once per process, by whichever thread draws first.
std::atomic<bool> warned_missing_gnuplot{false};

/// The executable `name` in a folder of PATH, or "" when there is none.
std::string program_on_path(const std::string& name) {
  const char* path = std::getenv("PATH");
  std::stringstream folders(path != nullptr ? path : "/usr/bin:/bin");
  for (std::string folder; std::getline(folders, folder, ':');) {
    const std::string candidate = (folder.empty() ? std::string(".") : folder) + "/" + name;
    if (access(candidate.c_str(), X_OK) == 0) return candidate;
  }
  return "";
}

/// Starts `gnuplot -e "terminal_set='<set>'; output_prefix='<prefix>'" plots.gp` in `dir` (the
/// script draws that set of images only, each to its temporary name), its output appended to
/// dir/plots.log. Returns the child's pid (-1: no gnuplot on PATH, or no fork).
pid_t start_gnuplot(const std::string& dir, const std::string& set) {
  // Everything the child needs is made before the fork: the process may have threads, so the
  // child calls only async-signal-safe functions (no allocation, no PATH search) until execv.
  const std::string gnuplot = program_on_path("gnuplot");
  if (gnuplot.empty()) return -1;
  std::cout.flush();
  std::cerr.flush();
  const std::string select = "terminal_set='" + set + "'; output_prefix='" + partial_name_prefix() + "'";
  const char* const argv[] = {"gnuplot", "-e", select.c_str(), "plots.gp", nullptr};
  const pid_t pid = fork();
  if (pid != 0) return pid;
  unblock_interrupt_signals();  // gnuplot stops on a signal as any program
#ifdef __linux__
  prctl(PR_SET_PDEATHSIG, SIGKILL);  // a killed run leaves no gnuplot drawing into its folder
#endif
  if (chdir(dir.c_str()) != 0) _exit(126);
  const int fd = open("plots.log", O_WRONLY | O_CREAT | O_APPEND, 0644);
  if (fd >= 0) {
    dup2(fd, STDOUT_FILENO);
    dup2(fd, STDERR_FILENO);
    close(fd);
  }
  const int null_in = open("/dev/null", O_RDONLY);
  if (null_in >= 0) dup2(null_in, STDIN_FILENO);
  execv(gnuplot.c_str(), const_cast<char* const*>(argv));
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

/// What is wrong with the image gnuplot left at `file` ("" when it is whole): missing, empty, or
/// cut before its end (an SVG ends with </svg>, a PNG with its IEND chunk) - a full disk or a
/// file-size limit leaves such files while gnuplot still exits 0.
std::string image_defect(const std::string& file, const std::string& ext) {
  std::ifstream in(file, std::ios::binary | std::ios::ate);
  if (!in) return "gnuplot drew no image";
  const std::streamoff size = in.tellg();
  if (size <= 0) return "gnuplot left an empty image";
  const std::streamoff tail_size = std::min<std::streamoff>(size, 64);
  std::string tail(static_cast<std::size_t>(tail_size), '\0');
  in.seekg(size - tail_size);
  in.read(tail.data(), tail_size);
  if (!in) return "cannot read the image gnuplot drew";
  if (ext == "svg") {
    const auto last = tail.find_last_not_of(" \t\r\n");
    const std::string end = "</svg>";
    if (last == std::string::npos || last + 1 < end.size() || tail.compare(last + 1 - end.size(), end.size(), end) != 0)
      return "gnuplot left an incomplete SVG (it does not end with </svg>)";
  } else {
    static const std::string iend("IEND\xAE\x42\x60\x82", 8);
    if (tail.size() < iend.size() || tail.compare(tail.size() - iend.size(), iend.size(), iend) != 0)
      return "gnuplot left an incomplete PNG (no IEND chunk at its end)";
  }
  return "";
}

}  // namespace

std::string gnuplot_number(double v, int digits) {
  if (!std::isfinite(v)) return "?";
  char b[40];
  std::snprintf(b, sizeof b, "%.*g", digits, v);
  return b;
}

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
  // The program has gnuplot draw each image to its temporary name (output_prefix), checks it and
  // renames it into place (output_files.hpp); run by hand, the script draws the final names.
  gp << "if (!exists(\"terminal_set\")) terminal_set = \"all\"\n"
     << "if (!exists(\"output_prefix\")) output_prefix = \"\"\n";
  for (const std::string ext : {"svg", "png"}) {
    gp << "\n# ---- " << ext << "\n"
       << "if (terminal_set eq \"all\" || terminal_set eq \"" << ext << "\") {\n"
       << (ext == "svg" ? "set terminal svg size 900,650 enhanced\n" : "eval \"set terminal \".png_term\n");
    for (const auto& fig : figures) {
      gp << "reset\nset datafile missing \"?\"\nset output output_prefix.\"" << fig.stem << "." << ext << "\"\n"
         << fig.body << "unset output\n";
      images.push_back(path(fig.stem + "." + ext));
    }
    gp << "}\n";
  }
  write_file_whole(path("plots.gp"), gp.str());
  write_file_whole(path("plots.log"), "");

  const pid_t svg = start_gnuplot(dir, "svg"), png = start_gnuplot(dir, "png");
  const int svg_status = wait_gnuplot(svg), png_status = wait_gnuplot(png);
  auto remove_partials = [&] {
    for (const auto& img : images) std::remove(partial_path(img).c_str());
  };
  // 127 (no gnuplot) only when neither could start; one failed fork is a failure of its set.
  if (svg_status == 127 && png_status == 127) {
    remove_partials();
    if (!warned_missing_gnuplot.exchange(true))
      std::cerr << "warning: gnuplot not found: no plots (the script and data are in " << dir << "/plots.gp)\n";
    return {};
  }
  // Every image checked before any is reported: gnuplot's status, then the file itself.
  for (const auto& img : images) {
    const std::string ext = fs::path(img).extension() == ".svg" ? "svg" : "png";
    const int status = ext == "svg" ? svg_status : png_status;
    const std::string defect =
        status != 0 ? "gnuplot failed (exit " + std::to_string(status) + ")" : image_defect(partial_path(img), ext);
    if (!defect.empty()) {
      remove_partials();
      throw OutputError(img, defect + "; see " + path("plots.log"));
    }
  }
  for (const auto& img : images) commit_partial(partial_path(img), img);
  return images;
}

}  // namespace dc::output
