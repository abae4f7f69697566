#pragma once

namespace octaclay::core {

/// A rectangle of samples (texels) of an image: origin (x, y) = (column i, row j), size
/// width × height. The one rectangle type of every module.
struct TexelRect {
  int x = 0, y = 0, width = 0, height = 0;
  friend bool operator==(TexelRect a, TexelRect b) = default;
};

} // namespace octaclay::core
