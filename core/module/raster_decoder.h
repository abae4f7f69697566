#pragma once

// The C interface of liboctaclay_raster_decoder (core/module/raster_decoder.cpp): images other
// than PNG decoded by OpenCV's imgcodecs, in a module of its own that core loads (dlopen) only
// when such an image is read. imgcodecs brings about 120 libraries (GDAL's) that every process
// linked with it loaded at start: 60 ms of every octaclay-cli command.

#include <cstddef>

extern "C" {

/// Decodes an image file's bytes (JPEG, TIFF, BMP, WebP …: what OpenCV reads) into 32-bit floats
/// in [0, 1] (8- and 16-bit) or as stored (float), channels interleaved in R, G, B, A order (1,
/// 3 or 4 of them). Returns 0 with *pixels from malloc (free it with octaclay_free_raster), or
/// non-zero with a message in message (at most messageSize bytes, terminated).
int octaclay_decode_raster(const unsigned char* bytes, std::size_t size, int* width, int* height,
                           int* channels, float** pixels, char* message, std::size_t messageSize);

/// Frees what octaclay_decode_raster gave.
void octaclay_free_raster(float* pixels);
}

/// The names core looks the two functions up by.
#define OCTACLAY_DECODE_RASTER_SYMBOL "octaclay_decode_raster"
#define OCTACLAY_FREE_RASTER_SYMBOL "octaclay_free_raster"
