#pragma once

#include <CLI/CLI.hpp>

#include <functional>

namespace octaclay::app {

/// Exit codes of octaclay-cli (also in README.md).
enum ExitCode : int {
  kExitOk = 0,
  kExitInternal = 1,     ///< a bug: please report it
  kExitUsage = 2,        ///< bad arguments
  kExitInvalidInput = 3, ///< an input file that is not what it should be
  kExitIo = 4,           ///< a file that cannot be read or written
  kExitGl = 5,           ///< no usable OpenGL 4.3 (or a brush that does not compile)
};

/// Each subcommand registers itself on the app and returns the function that runs it after
/// parsing. The function returns an exit code or throws core::Error.
using CommandRunner = std::function<int()>;

struct Command {
  CLI::App* subcommand;
  CommandRunner run;
};

Command addNewCommand(CLI::App& app);
Command addInfoCommand(CLI::App& app);
Command addExportCommand(CLI::App& app);
Command addCompareCommand(CLI::App& app);
Command addStrokeCommand(CLI::App& app);
Command addBrushesCommand(CLI::App& app);
Command addImportCommand(CLI::App& app);
Command addLodCommand(CLI::App& app);
Command addCompressCommand(CLI::App& app);
Command addDecompressCommand(CLI::App& app);
Command addRelaxCommand(CLI::App& app);
Command addResizeCommand(CLI::App& app);
Command addRemeshCommand(CLI::App& app);
Command addObjectsCommand(CLI::App& app);
Command addAddCommand(CLI::App& app);
Command addTransformCommand(CLI::App& app);
Command addRemoveCommand(CLI::App& app);
Command addRenameCommand(CLI::App& app);
Command addDuplicateCommand(CLI::App& app);
Command addMergeCommand(CLI::App& app);

} // namespace octaclay::app
