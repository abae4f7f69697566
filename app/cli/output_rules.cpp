#include "output_rules.h"

#include "octaclay/core/error.h"
#include "octaclay/core/file_extension.h"

#include <algorithm>
#include <filesystem>

namespace octaclay::app {

namespace fs = std::filesystem;

void requireOutputExtension(const std::string& path, std::initializer_list<const char*> allowed,
                            const std::string& what) {
  const std::string ext = core::lowerExtension(path);
  if (std::any_of(allowed.begin(), allowed.end(), [&ext](const char* a) { return ext == a; }))
    return;
  std::string expected;
  std::size_t k = 0;
  for (const char* a : allowed) {
    expected += (k == 0 ? "" : k + 1 == allowed.size() ? " or " : ", ") + std::string(a);
    ++k;
  }
  throw core::Error(core::ErrorKind::InvalidArgument,
                    "cannot write " + what + " to " + path + ": its name must end in " + expected);
}

void requireNotInput(const std::string& output, const std::string& input,
                     const std::string& option) {
  std::error_code ec; // an output that does not exist yet is no input
  if (fs::equivalent(output, input, ec) && !ec)
    throw core::Error(core::ErrorKind::InvalidArgument,
                      option + " " + output + " is the input " + input +
                          ": this command would replace it; write to another file");
}

} // namespace octaclay::app
