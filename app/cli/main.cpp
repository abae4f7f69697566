#include "commands.h"

#include "octaclay/core/error.h"
#include "octaclay/gpu/brush_manifest.h"
#include "octaclay/gpu/gl_error.h"

#include <cctype>
#include <iostream>
#include <new>
#include <string>

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

// A token that is a value, not an option, though it starts with '-': a negative number or a
// list of them ("-0.5", "-1,0,0", "-.3").
bool looksLikeValue(const std::string& token) {
  return token.size() >= 2 &&
         (std::isdigit(static_cast<unsigned char>(token[1])) != 0 || token[1] == '.');
}

// CLI11 reports a missing argument before an unknown option ("document is required" for
// `relax --frobnicate`): name the option the user typed instead. Returns the first token after
// the subcommand that looks like an option and is none of its options, or "".
std::string unknownOption(CLI::App& cli, int argc, char** argv) {
  if (argc < 2) return {};
  CLI::App* sub = nullptr;
  try {
    sub = cli.get_subcommand(argv[1]);
  } catch (const CLI::Error&) {
    return {};
  }
  for (int k = 2; k < argc; ++k) {
    const std::string token = argv[k];
    if (token == "--") break;
    if (token.size() < 2 || token[0] != '-' || looksLikeValue(token)) continue;
    const std::string name =
        token[1] == '-' ? token.substr(0, token.find('=')) : token.substr(0, 2);
    if (name == "--help" || name == "-h") continue;
    if (sub->get_option_no_throw(name) == nullptr) return name;
  }
  return {};
}

} // namespace

int main(int argc, char** argv) {
  CLI::App cli{"octaclay-cli: create, inspect, convert and compare Octaclay documents "
               "(octahedral geometry images stored as .exr)"};
  cli.require_subcommand(1);
  const app::Command commands[] = {
      app::addNewCommand(cli),        app::addInfoCommand(cli),    app::addExportCommand(cli),
      app::addCompareCommand(cli),    app::addStrokeCommand(cli),  app::addBrushesCommand(cli),
      app::addImportCommand(cli),     app::addLodCommand(cli),     app::addCompressCommand(cli),
      app::addDecompressCommand(cli), app::addRelaxCommand(cli),   app::addResizeCommand(cli),
      app::addRemeshCommand(cli),     app::addObjectsCommand(cli), app::addAddCommand(cli),
      app::addTransformCommand(cli),  app::addRemoveCommand(cli),  app::addRenameCommand(cli),
      app::addDuplicateCommand(cli),  app::addMergeCommand(cli)};

  cli.set_version_flag("--version", std::string("octaclay-cli ") + OCTACLAY_VERSION);
  if (argc >= 2 && argv[1][0] != '-') {
    bool known = false;
    std::string names;
    for (const CLI::App* sub : cli.get_subcommands([](CLI::App*) { return true; })) {
      known = known || sub->get_name() == argv[1];
      names += (names.empty() ? "" : ", ") + sub->get_name();
    }
    if (!known) {
      std::cerr << "octaclay-cli: error: no subcommand '" << argv[1]
                << "' (the subcommands: " << names << ")\n";
      return app::kExitUsage;
    }
  }
  if (const std::string unknown = unknownOption(cli, argc, argv); !unknown.empty()) {
    std::cerr << "octaclay-cli: error: " << argv[1] << " has no option " << unknown
              << " (see octaclay-cli " << argv[1] << " --help)\n";
    return app::kExitUsage;
  }
  try {
    cli.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return cli.exit(e); // --help, --version
    // One line: what was wrong, and where to read what is right.
    std::string where;
    try {
      if (argc >= 2) where = " " + cli.get_subcommand(argv[1])->get_name();
    } catch (const CLI::Error&) { // not a subcommand: the general help
    }
    std::cerr << "octaclay-cli: error: " << e.what() << " (see octaclay-cli" << where
              << " --help)\n";
    return app::kExitUsage;
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
