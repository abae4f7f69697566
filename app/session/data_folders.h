#pragma once

// Where the modeller and the CLI find their built-in brushes and resources (materials, the
// environment map, icons): installed, in share/octaclay beside the executable's bin/ (as
// `cmake --install` and the .deb lay them out), else the source tree the binary was built from.

#include <filesystem>

namespace octaclay::app {

/// The installed data folder, `<executable's folder>/../share/octaclay`, when it holds a
/// brushes/ folder; empty when this binary is not installed (it runs from the build tree).
std::filesystem::path installedDataFolder();

/// The built-in brushes: the installed data folder's brushes/, else the source tree's
/// plugins/brushes.
std::filesystem::path builtInBrushes();

/// What the source tree's resources/ holds (materials/, environment/, …): the installed data
/// folder itself, else the source tree's resources/.
std::filesystem::path resourceFolder();

} // namespace octaclay::app
