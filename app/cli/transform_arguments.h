#pragma once

// --translate x,y,z, --rotate x,y,z (degrees) and --scale s | sx,sy,sz: how `add` and
// `transform` place an object, parsed and checked the same way for both.

#include "octaclay/core/document/object_transform.h"

#include <CLI/CLI.hpp>

#include <optional>
#include <string>

namespace octaclay::app {

struct TransformArguments {
  std::string translate, rotate, scale; ///< as typed; empty when not given
};

/// Adds --translate, --rotate and --scale to sub.
void addTransformOptions(CLI::App& sub, TransformArguments& arguments);

/// transform with every given option's components set (the others kept). Throws
/// core::Error(InvalidArgument) naming the option for a list that is not three finite numbers
/// (or one, for --scale), and for a result transformProblem refuses (a zero scale, a translation
/// beyond ±1e6…).
core::ObjectTransform appliedTransform(core::ObjectTransform transform,
                                       const TransformArguments& arguments);

/// "x", "y" or "z" as 0, 1, 2; throws core::Error(InvalidArgument) naming option otherwise.
int parseAxis(const std::string& text, const std::string& option);

} // namespace octaclay::app
