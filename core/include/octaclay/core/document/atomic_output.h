#pragma once

// The one output rule (DESIGN.md, "Rules every output follows"): every file a command or the
// modeller writes is staged as a temporary beside its target (`.stem.tmp-PID-N.ext`, the stem cut
// to 64 bytes), written with every write and close checked, fsynced, and renamed into place only
// when every file of its set was staged; a failure leaves the previous files whole and no temporary
// behind. Writers only produce bytes (into a ByteSink, streamed as the document's EXR is, or in
// memory first: other EXR files, glTF, OpenMesh formats); no other code opens an output file.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <span>
#include <string_view>
#include <vector>

namespace octaclay::core {

/// Where a staged file's bytes go: the one checked writer. Every write and the close are checked;
/// a failure throws Error(Io) naming the user's target and the reason (disk full, a size limit).
class ByteSink {
public:
  void write(std::span<const std::uint8_t> bytes);
  void write(std::string_view text);
  /// Writes bytes at a byte offset from the file's start (pwrite: the position write() appends at
  /// does not move), for formats that fill in a table at the front once the body is written.
  void writeAt(std::uint64_t offset, std::span<const std::uint8_t> bytes);

private:
  friend class OutputSet;
  ByteSink(int fd, const std::filesystem::path& shown) : fd_(fd), shown_(shown) {}
  int fd_;
  const std::filesystem::path& shown_;
};

/// Files written as a set: each stage() writes one temporary now; commit() renames them all into
/// place, holding an flock on each target folder so that two concurrent sets to the same place
/// never mix (the later commit wins whole). Dropping an uncommitted set removes its temporaries.
/// Temporaries are also removed on SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGUSR1, SIGUSR2, SIGALRM
/// and SIGPIPE (the process then dies of the signal as before); SIGXFSZ is ignored so a file-size
/// limit fails the write (EFBIG) instead of killing.
class OutputSet {
public:
  OutputSet() = default;
  OutputSet(const OutputSet&) = delete;
  OutputSet& operator=(const OutputSet&) = delete;
  ~OutputSet();

  /// Checks the target (requireWritableTarget), removes stale temporaries of dead runs beside it,
  /// creates a fresh temporary and calls write(sink) to fill it (in one go or in chunks); the
  /// temporary is then closed, checked and fsynced. On failure the temporary is removed and
  /// Error(Io) names `target` and the reason (write's own core::Error passes through).
  void stage(const std::filesystem::path& target, const std::function<void(ByteSink&)>& write);
  void stageBytes(const std::filesystem::path& target, std::span<const std::uint8_t> bytes);
  void stageText(const std::filesystem::path& target, std::string_view text);

  /// Renames every staged temporary over its target, in staging order, then fsyncs the folders.
  /// Throws Error(Io) when a rename fails (the files not yet renamed keep their previous state).
  void commit();

  /// The targets staged so far (committed or not), in order.
  const std::vector<std::filesystem::path>& targets() const;

private:
  struct Staged {
    std::filesystem::path target, temporary;
    int slot = -1; ///< in the signal handler's registry, or -1
  };
  void discard() noexcept;
  std::vector<Staged> staged_; ///< not yet renamed
  std::vector<std::filesystem::path> targets_;
};

/// A one-file set: stage(target, write), then commit().
void writeFileAtomically(const std::filesystem::path& target,
                         const std::function<void(ByteSink&)>& write);
void writeBytesAtomically(const std::filesystem::path& target, std::span<const std::uint8_t> bytes);

/// Throws Error(InvalidArgument) for an empty path, Error(Io) when the target's folder does not
/// exist, or the target exists and is not a regular file (a folder, device, FIFO or socket: such
/// a target is refused, never replaced).
void requireWritableTarget(const std::filesystem::path& target);

} // namespace octaclay::core
