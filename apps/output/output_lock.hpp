#pragma once
// One run per output folder: an exclusive lock (flock) on DIR/.dyncontact.lock, taken before
// anything in the folder is removed or solved. A second run into a locked folder is refused at
// once (InputError naming the folder and its key, exit 2) instead of mixing its files with the
// first's. The lock goes with the process (or the OutputFolderLock object); the lock file stays
// (removing it would let two runs lock two different files of the same name).
#include <string>

namespace dc::output {

class OutputFolderLock {
 public:
  /// Locks `dir` (an existing folder); throws InputError(key) when another run holds it or the
  /// lock file cannot be opened.
  OutputFolderLock(const std::string& dir, const std::string& key);
  ~OutputFolderLock();
  OutputFolderLock(const OutputFolderLock&) = delete;
  OutputFolderLock& operator=(const OutputFolderLock&) = delete;

  /// "DIR/.dyncontact.lock"
  static std::string file(const std::string& dir);

 private:
  int fd_ = -1;
};

}  // namespace dc::output
