#include "bounded_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

namespace octaclay::gpu::detail {
namespace {

[[noreturn]] void refuse(const std::filesystem::path& file, const std::string& reason) {
  throw BoundedFileError(file.string() + ": " + reason);
}

std::string systemReason(int error) {
  if (error == ELOOP) return "is a symbolic link loop";
  return std::string("cannot be read (") + std::strerror(error) + ")";
}

// What a stat says the file is, when it is not something to read.
std::string notRegular(const struct stat& info, const std::string& kind) {
  if (S_ISDIR(info.st_mode)) return "is a folder, not a " + kind;
  if (S_ISFIFO(info.st_mode)) return "is a named pipe, not a " + kind + " (not read)";
  if (S_ISSOCK(info.st_mode)) return "is a socket, not a " + kind + " (not read)";
  if (S_ISCHR(info.st_mode) || S_ISBLK(info.st_mode))
    return "is a device, not a " + kind + " (not read)";
  return "is not a regular file (not read)";
}

struct Descriptor {
  int fd;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

void checkInfo(const std::filesystem::path& file, const struct stat& info, std::uintmax_t limit,
               const std::string& kind) {
  if (!S_ISREG(info.st_mode)) refuse(file, notRegular(info, kind));
  if (static_cast<std::uintmax_t>(info.st_size) > limit)
    refuse(file, "is " + std::to_string(info.st_size) + " bytes, more than the " +
                     std::to_string(limit) + " a " + kind + " may have (not read)");
}

} // namespace

std::string readBoundedFile(const std::filesystem::path& file, std::uintmax_t limit,
                            const std::string& kind) {
  struct stat info {};
  if (::stat(file.c_str(), &info) != 0) refuse(file, systemReason(errno));
  checkInfo(file, info, limit, kind);
  // Non-blocking: the name may have become a FIFO since the stat.
  const Descriptor in{::open(file.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC)};
  if (in.fd < 0) refuse(file, systemReason(errno));
  if (::fstat(in.fd, &info) != 0) refuse(file, systemReason(errno));
  checkInfo(file, info, limit, kind);

  // At most limit + 1 bytes: a file that grew since the stat is refused, not read on and on.
  std::string text(static_cast<std::size_t>(info.st_size) + 1, '\0');
  std::size_t done = 0;
  for (;;) {
    if (done == text.size()) {
      if (text.size() > limit)
        refuse(file, "grew past " + std::to_string(limit) + " bytes while read");
      text.resize(std::min<std::size_t>(limit + 1, text.size() * 2));
    }
    const ssize_t got = ::read(in.fd, text.data() + done, text.size() - done);
    if (got < 0) {
      if (errno == EINTR) continue;
      refuse(file, systemReason(errno));
    }
    if (got == 0) break;
    done += static_cast<std::size_t>(got);
  }
  text.resize(done);
  return text;
}

} // namespace octaclay::gpu::detail
