#pragma once

// The procedural matcaps the modeller's View ▸ Material offers (resources/matcaps/<id>.png):
// each pixel is the colour a sphere seen head-on shows where its view-space normal is
// (x, y, sqrt(1 - x² - y²)), lit by fixed lights. Nothing random, nothing downloaded: the same
// build writes the same bytes, CC0-1.0.

#include "octaclay/core/document/image_io.h"

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace octaclay::tools {

/// The ids of the generated matcaps, in menu order: clay, red-wax, chrome, skin.
std::vector<std::string> generatedMatcapIds();

/// The RGB matcap `id` at size × size texels: x right, y up (the top row is the sphere's top);
/// texels outside the disc repeat the rim's colour, so linear filtering at the rim blends
/// nothing foreign. Throws std::invalid_argument for an unknown id or a size under 16.
core::RasterImage generateMatcap(std::string_view id, int size);

/// Writes folder/<id>.png (256², RGB) for every generated matcap, creating the folder. Throws
/// core::Error when a file cannot be written.
void writeMatcaps(const std::filesystem::path& folder);

} // namespace octaclay::tools
