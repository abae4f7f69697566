#pragma once

// The one output rule (DESIGN.md, "Rules every output follows"): every file a command or the
// modeller writes is staged as a temporary beside its target (`.stem.tmp-PID-N.ext`), written
// with every write and close checked, fsynced, and renamed into place only when every file of
// its set was staged; a failure leaves the previous files whole and no temporary behind.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <span>
#include <string_view>
#include <vector>

namespace octaclay::core {

/// Files written as a set: each stage() writes one temporary now; commit() renames them all into
/// place, holding an flock on each target folder so that two concurrent sets to the same place
/// never mix (the later commit wins whole). Dropping an uncommitted set removes its temporaries.
/// Temporaries are also removed on SIGINT and SIGTERM (the process then dies of the signal as
/// before); SIGXFSZ is ignored so a file-size limit fails the write (EFBIG) instead of killing.
class OutputSet {
public:
  OutputSet() = default;
  OutputSet(const OutputSet&) = delete;
  OutputSet& operator=(const OutputSet&) = delete;
  ~OutputSet();

  /// Checks the target (requireWritableTarget), removes stale temporaries of dead runs beside it,
  /// creates a fresh temporary and calls write(temporary); write must report a failed write or
  /// close by throwing. The temporary is then fsynced. On failure the temporary is removed and
  /// Error(Io) names `target` and the reason (write's own core::Error passes through).
  void stage(const std::filesystem::path& target,
             const std::function<void(const std::filesystem::path& temporary)>& write);
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
                         const std::function<void(const std::filesystem::path& temporary)>& write);
void writeBytesAtomically(const std::filesystem::path& target, std::span<const std::uint8_t> bytes);

/// Throws Error(InvalidArgument) for an empty path, Error(Io) when the target's folder does not
/// exist, or the target exists and is not a regular file (a folder, device, FIFO or socket: such
/// a target is refused, never replaced).
void requireWritableTarget(const std::filesystem::path& target);

/// Writes `bytes` to `path` (created or truncated), checking every write and the close; errors
/// name `shown` (the user's target, not the temporary) and the reason. For stage()'s callbacks.
void writeBytesToFile(const std::filesystem::path& path, std::span<const std::uint8_t> bytes,
                      const std::filesystem::path& shown);

} // namespace octaclay::core
