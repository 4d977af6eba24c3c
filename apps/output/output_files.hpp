#pragma once
// Result files written whole or not at all: each file is written under a temporary name in its
// own folder (".partial-<pid>-<name>") and renamed into place, so a reader (or a run killed
// mid-write, or a full disk) never leaves a cut file under a result's name. A failed write is an
// OutputError naming the file and the system's reason; the command line exits 5 for it.
#include <stdexcept>
#include <string>
#include <string_view>

namespace dc {

/// A result file that could not be written (disk full, file-size limit, permissions).
class OutputError : public std::runtime_error {
 public:
  /// `error_number`: the errno of the failed call (0 when the reason is not a system error).
  OutputError(std::string path, const std::string& reason, int error_number = 0)
      : std::runtime_error(path + ": " + reason), path_(std::move(path)), reason_(reason), errno_(error_number) {}
  const std::string& path() const { return path_; }
  const std::string& reason() const { return reason_; }
  int error_number() const { return errno_; }

 private:
  std::string path_, reason_;
  int errno_;
};

namespace output {

/// The prefix of every temporary name; a file starting with it is a temporary (stale once its
/// run has ended: open_output_folder removes them).
inline constexpr std::string_view kPartialPrefix = ".partial-";

/// ".partial-<pid>-": what this process puts before a file's name for its temporary.
std::string partial_name_prefix();

/// The temporary name of `path` in its folder for this process: dir/.partial-<pid>-<name>.
std::string partial_path(const std::string& path);

/// Writes `text` to `path` whole: to partial_path(path), every write and the close checked,
/// then renamed into place. On failure the temporary is removed and OutputError is thrown
/// (the message names `path` and strerror, e.g. "No space left on device").
void write_file_whole(const std::string& path, std::string_view text);

/// Renames a complete temporary into place (`path`); throws OutputError (the temporary removed).
void commit_partial(const std::string& partial, const std::string& path);

}  // namespace output
}  // namespace dc
