#pragma once

// The procedural generator of the resources Octaclay ships (resources/materials/<id>/ and
// resources/environment/studio.png). Everything is computed from fixed seeds with integer
// hashing, so the same build writes the same bytes every time and nothing is downloaded.

#include "octaclay/core/document/image_io.h"

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace octaclay::tools {

/// The four maps of one material, each size × size: height, specular and reflectivity 1 channel,
/// colour 3 channels (RGB; the catalog reads a missing alpha as full coverage).
struct MaterialMaps {
  core::RasterImage height, colour, specular, reflectivity;
};

/// The ids of the generated materials, in the order writeResources writes them:
/// brick, stone, wood, red-plastic, mirror.
std::vector<std::string> generatedMaterialIds();

/// Computes the maps of material `id` (one of generatedMaterialIds()) at size × size texels; the
/// maps tile seamlessly. size must be a multiple of 16 (the patterns' periods divide it).
/// Throws std::invalid_argument for an unknown id or a bad size.
MaterialMaps generateMaterial(std::string_view id, int size);

/// Computes the studio environment map, width × height texels of equirectangular RGB (x is the
/// azimuth, y the polar angle from straight up): a soft sky-to-floor gradient with three
/// softbox lights. Wraps seamlessly in x. width and height must be positive.
core::RasterImage generateStudioEnvironment(int width, int height);

/// Writes resourcesFolder/materials/<id>/{material.json, height.png, colour.png, specular.png,
/// reflectivity.png} for every generated material (256² maps) and
/// resourcesFolder/environment/studio.png (512 × 256), creating folders as needed and replacing
/// existing files. Throws core::Error when a file cannot be written,
/// std::filesystem::filesystem_error when a folder cannot be created.
void writeResources(const std::filesystem::path& resourcesFolder);

} // namespace octaclay::tools
