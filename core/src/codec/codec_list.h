#pragma once

// The codec factories the registry (codec_registry.cpp) lists, one per source file.

#include "octaclay/core/codec/codec.h"

namespace octaclay::core {

Codec makeBytepackCodec();
Codec makeDctCodec();
Codec makeExrCodec();
Codec makeWaveletCodec();
Codec makeLosslessCodec();

} // namespace octaclay::core
