#pragma once

#include "octaclay/gpu/brush_manifest.h"
#include "octaclay/gpu/stroke.h"

#include <string>

// A stroke's settings checked before its first dab, and the error a setting out of bounds gives.
namespace octaclay::gpu::detail {

/// Throws core::Error(InvalidArgument) with the message.
[[noreturn]] void badSetting(const std::string& message);

/// Throws core::Error(InvalidArgument) for a parameter, view or spacing that is not finite, or a
/// parameter outside its [min, max] (a material parameter is an index: any finite value).
void checkSettings(const BrushManifest& brush, const StrokeSettings& settings);

} // namespace octaclay::gpu::detail
