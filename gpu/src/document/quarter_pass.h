#pragma once

// The dispatch the tile reductions share (tile_bounds_pass, area_normal_pass): a compute program
// reads the positions texture (unit 0) and a list of tile quarters (shader storage binding 2),
// writes a fixed number of bytes per quarter (binding 3), and only those are read back.

#include "octaclay/gpu/gl_objects.h"

#include <array>
#include <cstddef>
#include <span>
#include <vector>

namespace octaclay::gpu::detail {

class QuarterPass {
public:
  /// The program from the built-in shader file (gpu/shaders/), compiled on first use.
  explicit QuarterPass(const char* shader) : shader_(shader) {}
  /// The program, for its uniforms: set them between use() and run().
  const Program& use();
  /// Runs over quarters (x, y, width, height in samples), 64 to a group, with positions bound
  /// to unit 0 (the unit's texture put back after), and reads back bytesPerQuarter a quarter
  /// into out (resized). Waits for the passes that wrote positions. Throws GlError naming what.
  void run(const Texture& positions, std::span<const std::array<int, 4>> quarters,
           std::size_t bytesPerQuarter, std::vector<std::byte>& out, const char* what);

private:
  const char* shader_;
  Program program_;
  Buffer quarters_, results_;
  std::size_t resultBytes_ = 0; // results_'s size
};

} // namespace octaclay::gpu::detail
