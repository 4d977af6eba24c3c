#include "output_files.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

namespace dc::output {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what, int err, const std::string& partial) {
  ::unlink(partial.c_str());
  throw OutputError(path, what + ": " + std::strerror(err), err);
}

}  // namespace

std::string partial_name_prefix() { return std::string(kPartialPrefix) + std::to_string(::getpid()) + "-"; }

std::string partial_path(const std::string& path) {
  const std::filesystem::path p(path);
  return (p.parent_path() / (partial_name_prefix() + p.filename().string())).string();
}

void write_file_whole(const std::string& path, std::string_view text) {
  const std::string partial = partial_path(path);
  const int fd = ::open(partial.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) {
    const int err = errno;
    throw OutputError(path, std::string("cannot write: ") + std::strerror(err), err);
  }
  const char* at = text.data();
  std::size_t left = text.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, at, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      const int err = errno;
      ::close(fd);
      fail(path, "cannot write", err, partial);
    }
    at += n;
    left -= static_cast<std::size_t>(n);
  }
  if (::close(fd) != 0) fail(path, "cannot write", errno, partial);
  commit_partial(partial, path);
}

void commit_partial(const std::string& partial, const std::string& path) {
  if (std::rename(partial.c_str(), path.c_str()) != 0) fail(path, "cannot rename its temporary into place", errno, partial);
}

}  // namespace dc::output
