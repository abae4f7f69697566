#pragma once

// File names' extensions as every writer and reader compares them: case-insensitively.

#include <filesystem>
#include <string>

namespace octaclay::core {

/// The path's extension with its dot, in lower case (ASCII only): "Model.OBJ" gives ".obj", a
/// name without an extension gives "".
std::string lowerExtension(const std::filesystem::path& path);

} // namespace octaclay::core
