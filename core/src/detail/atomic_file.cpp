// The atomic writer behind every output: staged temporaries, checked writes, fsync, rename under
// a folder lock (atomic_output.h).

#include "detail/temporary_registry.h"

#include "octaclay/core/document/atomic_output.h"
#include "octaclay/core/error.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <charconv>
#include <string>
#include <system_error>

namespace octaclay::core {
namespace fs = std::filesystem;

namespace {

std::atomic<unsigned> temporaryCounter{0};

[[noreturn]] void failWrite(const fs::path& target, const std::string& why) {
  throw Error(ErrorKind::Io, "cannot write " + target.string() + ": " + why);
}

std::string reason(int error) {
  return std::generic_category().message(error); // thread-safe, unlike strerror
}

// Libraries (OpenEXR) name the file they wrote: the user asked for the target, not the hidden
// temporary.
fs::path folderOf(const fs::path& target) {
  return target.parent_path().empty() ? fs::path(".") : target.parent_path();
}

// The hidden name keeps at most this many bytes of the target's stem, so that any legal target
// name (up to 255 bytes) has a temporary of a legal length beside it.
constexpr std::size_t kTemporaryStemBytes = 64;

std::string temporaryPrefix(const fs::path& target) {
  return "." + target.stem().string().substr(0, kTemporaryStemBytes) + ".tmp-";
}

// `.stem.tmp-PID-N.ext` → PID, or 0 when the name is not one of target's temporaries.
pid_t temporaryOwner(const std::string& name, const fs::path& target) {
  const std::string prefix = temporaryPrefix(target), ext = target.extension().string();
  if (name.size() <= prefix.size() + ext.size() || name.compare(0, prefix.size(), prefix) != 0 ||
      name.compare(name.size() - ext.size(), ext.size(), ext) != 0)
    return 0;
  const char* first = name.data() + prefix.size();
  const char* last = name.data() + name.size() - ext.size();
  long pid = 0;
  unsigned counter = 0;
  auto [afterPid, pidError] = std::from_chars(first, last, pid);
  if (pidError != std::errc() || afterPid == last || *afterPid != '-' || pid <= 0) return 0;
  auto [end, counterError] = std::from_chars(afterPid + 1, last, counter);
  if (counterError != std::errc() || end != last) return 0;
  return static_cast<pid_t>(pid);
}

// A killed run (SIGKILL, power loss) cannot clean up: its temporaries go with the next save.
void removeStaleTemporaries(const fs::path& target) {
  std::error_code ec;
  for (fs::directory_iterator it(folderOf(target), ec), end; !ec && it != end; it.increment(ec)) {
    const pid_t owner = temporaryOwner(it->path().filename().string(), target);
    if (owner == 0 || owner == ::getpid()) continue;
    if (::kill(owner, 0) != 0 && errno == ESRCH) {
      std::error_code ignored;
      fs::remove(it->path(), ignored);
    }
  }
}

// Holds an exclusive flock on each folder a set commits into (sorted, so two sets never wait
// on each other in a cycle); released when destroyed.
class FolderLocks {
public:
  explicit FolderLocks(std::vector<fs::path> folders) {
    std::sort(folders.begin(), folders.end());
    folders.erase(std::unique(folders.begin(), folders.end()), folders.end());
    for (const fs::path& folder : folders) {
      const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
      if (fd < 0) continue; // the renames below report the folder's problem
      while (::flock(fd, LOCK_EX) != 0 && errno == EINTR) {
      }
      fds_.push_back(fd);
    }
  }
  FolderLocks(const FolderLocks&) = delete;
  FolderLocks& operator=(const FolderLocks&) = delete;
  ~FolderLocks() {
    for (const int fd : fds_)
      ::close(fd);
  }
  void syncAll() const {
    for (const int fd : fds_)
      ::fsync(fd);
  }

private:
  std::vector<int> fds_;
};

} // namespace

void requireWritableTarget(const fs::path& target) {
  if (target.empty()) throw Error(ErrorKind::InvalidArgument, "no output file given: name one");
  const fs::path folder = folderOf(target);
  std::error_code ec;
  if (!fs::is_directory(folder, ec))
    failWrite(target, "folder " + folder.string() + " does not exist");
  const fs::file_status status = fs::status(target, ec);
  if (ec || status.type() == fs::file_type::not_found || status.type() == fs::file_type::regular)
    return;
  if (status.type() == fs::file_type::directory) failWrite(target, "it is a folder");
  failWrite(target, "it is not a regular file (a device, pipe or socket); it is refused, not "
                    "replaced: choose a file path");
}

void ByteSink::write(std::span<const std::uint8_t> bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd_, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) failWrite(shown_, reason(n < 0 ? errno : ENOSPC));
    done += static_cast<std::size_t>(n);
  }
}

void ByteSink::writeAt(std::uint64_t offset, std::span<const std::uint8_t> bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n =
        ::pwrite(fd_, bytes.data() + done, bytes.size() - done, static_cast<off_t>(offset + done));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) failWrite(shown_, reason(n < 0 ? errno : ENOSPC));
    done += static_cast<std::size_t>(n);
  }
}

void ByteSink::write(std::string_view text) {
  write(std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
}

OutputSet::~OutputSet() {
  discard();
}

void OutputSet::discard() noexcept {
  for (const Staged& s : staged_) {
    ::unlink(s.temporary.c_str());
    detail::unregisterTemporary(s.slot);
  }
  staged_.clear();
}

void OutputSet::stage(const fs::path& target, const std::function<void(ByteSink&)>& write) {
  requireWritableTarget(target);
  for (const Staged& s : staged_)
    if (s.target == target) failWrite(target, "the same file is written twice by one command");
  removeStaleTemporaries(target);

  Staged staged{target, {}, -1};
  int fd = -1;
  for (int attempt = 0; fd < 0 && attempt < 100; ++attempt) {
    staged.temporary = target;
    staged.temporary.replace_filename(temporaryPrefix(target) + std::to_string(::getpid()) + "-" +
                                      std::to_string(temporaryCounter++) +
                                      target.extension().string());
    // Registered before it exists, so a signal at any moment finds it.
    staged.slot = detail::registerTemporary(staged.temporary);
    fd = ::open(staged.temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) break;
    const int error = errno;
    detail::unregisterTemporary(staged.slot);
    if (error != EEXIST) failWrite(target, reason(error));
  }
  if (fd < 0) failWrite(target, "no free temporary name beside it");
  ::close(fd);
  staged_.push_back(staged);
  targets_.push_back(target);
  const auto dropLast = [&] {
    staged_.pop_back();
    targets_.pop_back();
    ::unlink(staged.temporary.c_str());
    detail::unregisterTemporary(staged.slot);
  };

  try {
    const int out = ::open(staged.temporary.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
    if (out < 0) failWrite(target, reason(errno));
    try {
      ByteSink sink(out, target);
      write(sink);
    } catch (...) {
      ::close(out);
      throw;
    }
    const bool synced = ::fsync(out) == 0 || errno == EINVAL || errno == EROFS;
    const int syncError = errno;
    if (::close(out) != 0) failWrite(target, reason(errno));
    if (!synced) failWrite(target, reason(syncError));
    // A replaced file keeps its permissions (set only now: the writer may need to open it).
    struct stat previous {};
    if (::stat(target.c_str(), &previous) == 0)
      ::chmod(staged.temporary.c_str(), previous.st_mode & 0777);
  } catch (const Error&) {
    dropLast();
    throw;
  } catch (const std::bad_alloc&) {
    dropLast();
    throw;
  } catch (const std::exception& e) {
    dropLast();
    failWrite(target, e.what());
  }
}

void OutputSet::stageBytes(const fs::path& target, std::span<const std::uint8_t> bytes) {
  stage(target, [&](ByteSink& sink) { sink.write(bytes); });
}

void OutputSet::stageText(const fs::path& target, std::string_view text) {
  stageBytes(target, std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
}

void OutputSet::commit() {
  std::vector<fs::path> folders;
  for (const Staged& s : staged_)
    folders.push_back(fs::absolute(folderOf(s.target)).lexically_normal());
  const FolderLocks locks(std::move(folders));
  while (!staged_.empty()) {
    const Staged& s = staged_.front();
    if (::rename(s.temporary.c_str(), s.target.c_str()) != 0) {
      const int error = errno;
      const fs::path target = s.target;
      discard();
      failWrite(target, reason(error));
    }
    detail::unregisterTemporary(s.slot);
    staged_.erase(staged_.begin());
  }
  locks.syncAll();
}

const std::vector<fs::path>& OutputSet::targets() const {
  return targets_;
}

void writeFileAtomically(const fs::path& target, const std::function<void(ByteSink&)>& write) {
  OutputSet set;
  set.stage(target, write);
  set.commit();
}

void writeBytesAtomically(const fs::path& target, std::span<const std::uint8_t> bytes) {
  OutputSet set;
  set.stageBytes(target, bytes);
  set.commit();
}

} // namespace octaclay::core
