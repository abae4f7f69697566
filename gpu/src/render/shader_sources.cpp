#include "shader_sources.h"

#include "octaclay/gpu/gl_error.h"

#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string_view>

namespace octaclay::gpu::detail {

const std::map<std::string_view, std::string_view>& embeddedShaders();

std::string builtInShader(const std::string& name) {
  if (const char* dir = std::getenv("OCTACLAY_SHADER_DIR")) {
    std::ifstream in(std::string(dir) + "/" + name);
    if (in) {
      std::stringstream text;
      text << in.rdbuf();
      return text.str();
    }
  }
  const auto& shaders = embeddedShaders();
  const auto found = shaders.find(name);
  if (found == shaders.end()) throw GlError("no built-in shader named " + name);
  return std::string(found->second);
}

} // namespace octaclay::gpu::detail
