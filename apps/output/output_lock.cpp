#include "output_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

#include "errors.hpp"

namespace dc::output {
namespace {

/// The process id the holder wrote into the lock file ("" when none).
std::string holder(int fd) {
  char buf[32] = {};
  const ssize_t n = ::pread(fd, buf, sizeof buf - 1, 0);
  std::string pid(buf, n > 0 ? static_cast<std::size_t>(n) : 0);
  while (!pid.empty() && (pid.back() == '\n' || pid.back() == ' ')) pid.pop_back();
  return pid.find_first_not_of("0123456789") == std::string::npos ? pid : std::string();
}

}  // namespace

std::string OutputFolderLock::file(const std::string& dir) {
  return (std::filesystem::path(dir) / ".dyncontact.lock").string();
}

OutputFolderLock::OutputFolderLock(const std::string& dir, const std::string& key) {
  const std::string path = file(dir);
  bool writable = true;
  fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) {  // a lock file this user cannot write (another user's): flock works read-only
    writable = false;
    fd_ = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  }
  if (fd_ < 0) {
    const int err = errno;
    throw InputError(key, "cannot write into the output folder '" + dir + "' (its lock file " + path +
                              "): " + std::strerror(err));
  }
  int rc = 0;
  while ((rc = ::flock(fd_, LOCK_EX | LOCK_NB)) != 0 && errno == EINTR) {
  }
  if (rc != 0) {
    const int err = errno;
    const std::string pid = err == EWOULDBLOCK ? holder(fd_) : std::string();
    ::close(fd_);
    fd_ = -1;
    if (err == EWOULDBLOCK)
      throw InputError(key, "the output folder '" + dir + "' is in use by another dyncontact run" +
                                (pid.empty() ? std::string() : " (process " + pid + ")") +
                                "; wait for it to finish or choose another folder");
    throw InputError(key, "cannot lock the output folder '" + dir + "': " + std::strerror(err));
  }
  if (writable && ::ftruncate(fd_, 0) == 0) {  // who holds it, for a refused run's message (best effort)
    const std::string pid = std::to_string(::getpid()) + "\n";
    [[maybe_unused]] const ssize_t written = ::pwrite(fd_, pid.data(), pid.size(), 0);
  }
}

OutputFolderLock::~OutputFolderLock() {
  if (fd_ >= 0) ::close(fd_);  // closing the last descriptor releases the lock
}

}  // namespace dc::output
