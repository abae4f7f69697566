#pragma once

// What every command checks of its outputs before it reads or writes anything (issue 34): an
// output carries the extension of the format written, and is never one of the command's inputs
// unless the command writes that document in place on purpose (stroke, relax, remesh, resize).

#include <initializer_list>
#include <string>

namespace octaclay::app {

/// Throws core::Error(InvalidArgument) unless path's extension (any case) is one of allowed
/// (".exr", ".png", …): "cannot write <what> to PATH: use .exr" names the expected ones.
void requireOutputExtension(const std::string& path, std::initializer_list<const char*> allowed,
                            const std::string& what);

/// Throws core::Error(InvalidArgument) when output names the same file as input: the same
/// path, or the same file through another name (a link). option names the flag in the message.
void requireNotInput(const std::string& output, const std::string& input,
                     const std::string& option = "-o");

} // namespace octaclay::app
