#pragma once

// The temporaries alive in this process, for a signal handler that removes them: SIGINT,
// SIGTERM, SIGHUP, SIGQUIT, SIGUSR1, SIGUSR2, SIGALRM and SIGPIPE unlink every registered
// temporary, then die of the signal as before; SIGXFSZ is
// ignored, so a write over the file-size limit fails with EFBIG and the writer cleans up.

#include <filesystem>

namespace octaclay::core::detail {

/// Installs the handlers once (only where the signal still has its default disposition, so a
/// host's own handlers stay), then records `path`. Returns its slot, or -1 when the registry is
/// full or the path too long (the temporary is then still removed by every normal error path).
int registerTemporary(const std::filesystem::path& path);

/// Forgets a slot from registerTemporary (-1 is ignored).
void unregisterTemporary(int slot);

} // namespace octaclay::core::detail
