#include "detail/atomic_file.h"

#include "octaclay/core/error.h"

#include <unistd.h>

#include <random>
#include <system_error>

namespace octaclay::core::detail {
namespace fs = std::filesystem;

namespace {

fs::path temporaryBeside(const fs::path& path) {
  std::random_device device;
  const auto tag = std::to_string(::getpid()) + "-" + std::to_string(device() % 1000000u);
  fs::path temp = path;
  temp.replace_filename("." + path.stem().string() + ".tmp-" + tag + path.extension().string());
  return temp;
}

} // namespace

void writeAtomically(const fs::path& path, const std::function<void(const fs::path&)>& write) {
  const fs::path parent = path.parent_path().empty() ? fs::path(".") : path.parent_path();
  std::error_code ec;
  if (!fs::is_directory(parent, ec))
    throw Error(ErrorKind::Io, "cannot write " + path.string() + ": folder " + parent.string() +
                                   " does not exist");
  if (fs::is_directory(path, ec))
    throw Error(ErrorKind::Io, "cannot write " + path.string() + ": it is a folder");

  const fs::path temp = temporaryBeside(path);
  try {
    write(temp);
  } catch (const Error&) {
    fs::remove(temp, ec);
    throw;
  } catch (const std::exception& e) {
    fs::remove(temp, ec);
    throw Error(ErrorKind::Io, "cannot write " + path.string() + ": " + e.what());
  }
  fs::rename(temp, path, ec);
  if (ec) {
    const std::string why = ec.message();
    fs::remove(temp, ec);
    throw Error(ErrorKind::Io, "cannot write " + path.string() + ": " + why);
  }
}

} // namespace octaclay::core::detail
