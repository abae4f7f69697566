#pragma once

namespace octaclay::core {

/// The image layers a stroke or a brush can change: the one layer enum of every module.
/// Texels are float, editLayerChannels() per texel.
enum class EditLayer { Positions, Diffuse, Feature, Mask };

/// Floats per texel of layer: Positions 4 (xyz + saliency), Diffuse 4, Feature 3, Mask 1.
int editLayerChannels(EditLayer layer);

} // namespace octaclay::core
