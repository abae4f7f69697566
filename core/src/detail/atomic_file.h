#pragma once

#include <filesystem>
#include <functional>

namespace octaclay::core::detail {

/// One file through the one output rule (octaclay/core/document/atomic_output.h): calls
/// write(temporary) with a fresh path beside `path` that keeps its extension, fsyncs it and
/// renames it over `path`. On any failure the temporary is removed, `path` is untouched and
/// Error(Io) is thrown naming `path` (write's own core::Error passes through unchanged).
void writeAtomically(const std::filesystem::path& path,
                     const std::function<void(const std::filesystem::path&)>& write);

} // namespace octaclay::core::detail
