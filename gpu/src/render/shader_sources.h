#pragma once

#include <string>

namespace octaclay::gpu::detail {

/// The text of a built-in shader (a file name in gpu/shaders/). Reads the live file from
/// $OCTACLAY_SHADER_DIR when that is set. Throws GlError for an unknown name.
std::string builtInShader(const std::string& name);

} // namespace octaclay::gpu::detail
