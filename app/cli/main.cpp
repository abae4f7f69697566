#include "commands.h"

#include "octaclay/core/error.h"
#include "octaclay/gpu/brush_manifest.h"
#include "octaclay/gpu/gl_error.h"

#include <iostream>
#include <new>

using namespace octaclay;

namespace {

int exitCodeFor(core::ErrorKind kind) {
  switch (kind) {
  case core::ErrorKind::InvalidArgument:
  case core::ErrorKind::UnknownId: // the commands name unknown brushes as bad arguments
  case core::ErrorKind::Cancelled: // as when a cancel was an InvalidArgument
    return app::kExitUsage;
  case core::ErrorKind::InvalidInput:
    return app::kExitInvalidInput;
  case core::ErrorKind::Io:
    return app::kExitIo;
  }
  return app::kExitInternal;
}

// `-o ''` names no file: a bad argument, reported before anything is read.
void requireNamedOutput(const CLI::App& subcommand) {
  const CLI::Option* output = subcommand.get_option_no_throw("--output");
  if (output && output->count() > 0 && output->as<std::string>().empty())
    throw core::Error(core::ErrorKind::InvalidArgument, "-o names no file: give an output path");
}

// Only `new`, `import`, `resize` and `remesh` allocate what --size asks for; anywhere else
// memory runs out on what an input file declares.
bool sizedByArgument(const CLI::App& subcommand) {
  return subcommand.get_name() == "new" || subcommand.get_name() == "import" ||
         subcommand.get_name() == "resize" || subcommand.get_name() == "remesh";
}

} // namespace

int main(int argc, char** argv) {
  CLI::App cli{"octaclay-cli: create, inspect, convert and compare Octaclay documents "
               "(octahedral geometry images stored as .exr)"};
  cli.require_subcommand(1);
  const app::Command commands[] = {
      app::addNewCommand(cli),        app::addInfoCommand(cli),   app::addExportCommand(cli),
      app::addCompareCommand(cli),    app::addStrokeCommand(cli), app::addBrushesCommand(cli),
      app::addImportCommand(cli),     app::addLodCommand(cli),    app::addCompressCommand(cli),
      app::addDecompressCommand(cli), app::addRelaxCommand(cli),  app::addResizeCommand(cli),
      app::addRemeshCommand(cli)};

  try {
    cli.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = cli.exit(e);
    return code == 0 ? app::kExitOk : app::kExitUsage;
  }

  const CLI::App* chosen = nullptr;
  try {
    for (const app::Command& command : commands)
      if (command.subcommand->parsed()) {
        chosen = command.subcommand;
        requireNamedOutput(*chosen);
        return command.run();
      }
  } catch (const core::Error& e) {
    std::cerr << "octaclay-cli: error: " << e.what() << "\n";
    return exitCodeFor(e.kind());
  } catch (const gpu::GlError& e) {
    std::cerr << "octaclay-cli: error: " << e.what() << "\n";
    return app::kExitGl;
  } catch (const gpu::BrushLoadError& e) {
    std::cerr << "octaclay-cli: error: " << e.what() << "\n";
    return app::kExitInvalidInput;
  } catch (const std::bad_alloc&) {
    if (chosen && sizedByArgument(*chosen)) {
      std::cerr << "octaclay-cli: error: out of memory; try a smaller --size\n";
      return app::kExitInternal;
    }
    std::cerr << "octaclay-cli: error: out of memory while reading the input: it declares more "
                 "data than this machine can hold (a damaged or hostile file?)\n";
    return app::kExitInvalidInput;
  } catch (const std::exception& e) {
    std::cerr << "octaclay-cli: internal error: " << e.what() << " (please report this)\n";
    return app::kExitInternal;
  }
  return app::kExitInternal;
}
