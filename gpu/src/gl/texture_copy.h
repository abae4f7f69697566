#pragma once

#include "octaclay/core/geometry/texel_rect.h"
#include "octaclay/gpu/gl_objects.h"

#include <epoxy/gl.h>

namespace octaclay::gpu::detail {

/// Copies the texels of r from one texture to the same place in another.
inline void copyRect(const Texture& from, const Texture& to, core::TexelRect r) {
  glCopyImageSubData(from.id(), GL_TEXTURE_2D, 0, r.x, r.y, 0, to.id(), GL_TEXTURE_2D, 0, r.x, r.y,
                     0, r.width, r.height, 1);
}

} // namespace octaclay::gpu::detail
