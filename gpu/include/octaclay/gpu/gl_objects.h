#pragma once

#include "octaclay/core/geometry/texel_rect.h"

#include <array>
#include <span>
#include <string>
#include <vector>

namespace octaclay::gpu {

/// Pixel formats of the images the engine keeps on the GPU.
enum class TextureFormat {
  Rgba32f, ///< positions (xyz) + saliency (w): float32 so edits round-trip bit-exactly
  Rgba16f, ///< diffuse colour
  R32f,    ///< single-channel float data
  Rgba8,   ///< unit vectors stored as v/2 + 1/2 (the normal map): a quarter of the bytes to sample
};

/// Move-only owner of a 2D texture. Can be empty, take ownership of a foreign id (adopt), stand
/// for one it does not own (wrap) and give its id back (release). All calls need the owning
/// context current on the calling thread.
class Texture {
public:
  Texture() = default;
  /// Allocates width × height texels of format, nearest filtering, clamped. Throws GlError.
  Texture(int width, int height, TextureFormat format);
  /// The same with room for `levels` mipmap levels (fill them with glGenerateMipmap).
  static Texture withLevels(int width, int height, TextureFormat format, int levels);
  /// Takes ownership of id: the texture deletes it.
  static Texture adopt(unsigned id, int width, int height, TextureFormat format);
  /// Stands for id without owning it: the texture never deletes it (its owner does, after the
  /// texture is gone).
  static Texture wrap(unsigned id, int width, int height, TextureFormat format);
  Texture(Texture&& other) noexcept;
  Texture& operator=(Texture&& other) noexcept;
  Texture(const Texture&) = delete;
  Texture& operator=(const Texture&) = delete;
  ~Texture();

  /// Writes region from floats, channels-per-texel as the format has (4 or 1), row-major.
  void upload(core::TexelRect region, std::span<const float> texels);
  /// Reads region back as floats, row-major.
  std::vector<float> read(core::TexelRect region) const;
  /// Reads region into a larger row-major float image: `out` is where the region's first texel
  /// goes, rows are rowLength texels apart, each texel `channels` floats (1, 3 or 4; channels
  /// the texture lacks read as 0, alpha as 1). Avoids a temporary and a copy per dab.
  void readInto(core::TexelRect region, float* out, int rowLength, int channels) const;
  /// Starts reading region into GL buffer `buffer` (a pixel-pack buffer) at byte offset, rows
  /// tight, each texel in the format's own layout (packedTexelBytes: RGBA half floats for
  /// Rgba16f): the read runs on the GPU's time; fence it and map the buffer later.
  void readToPackBuffer(core::TexelRect region, unsigned buffer, std::size_t offset) const;
  /// The bytes of one texel as readToPackBuffer writes it.
  std::size_t packedTexelBytes() const;
  /// Writes region from a larger row-major float image laid out as for readInto.
  void uploadFrom(core::TexelRect region, const float* in, int rowLength, int channels);

  unsigned id() const { return id_; }
  int width() const { return width_; }
  int height() const { return height_; }
  TextureFormat format() const { return format_; }
  int channels() const { return format_ == TextureFormat::R32f ? 1 : 4; }
  /// Gives up ownership and returns the id (the texture is empty after).
  unsigned release();
  /// Binds a framebuffer rendering into this texture (made once, kept with the texture).
  void bindAsTarget() const;
  /// Sets the texels of region to value (its first channels()), cleared on the GPU: no upload.
  /// The bound framebuffer and the scissor test are left as they were. Throws GlError.
  void fill(const std::array<float, 4>& value, core::TexelRect region);

private:
  Texture(int width, int height, TextureFormat format, int levels);
  unsigned framebuffer() const;

  unsigned id_ = 0;
  bool owned_ = true; // false: wrap()'s, deleted by its owner
  int width_ = 0, height_ = 0;
  TextureFormat format_ = TextureFormat::Rgba32f;
  mutable unsigned framebuffer_ = 0; // made on first use by read() or bindAsTarget()
};

/// Move-only owner of a framebuffer with one colour attachment.
class Framebuffer {
public:
  Framebuffer() = default;
  /// A framebuffer rendering into texture. Throws GlError naming the incompleteness.
  explicit Framebuffer(const Texture& target);
  Framebuffer(Framebuffer&& other) noexcept;
  Framebuffer& operator=(Framebuffer&& other) noexcept;
  Framebuffer(const Framebuffer&) = delete;
  Framebuffer& operator=(const Framebuffer&) = delete;
  ~Framebuffer();

  void bind() const;
  unsigned id() const { return id_; }
  /// Gives up ownership and returns the id.
  unsigned release();

private:
  unsigned id_ = 0;
};

/// Move-only owner of a buffer object (vertex, shader-storage, … data).
class Buffer {
public:
  Buffer() = default;
  /// A new, empty buffer object. Throws GlError.
  static Buffer create();
  Buffer(Buffer&& other) noexcept;
  Buffer& operator=(Buffer&& other) noexcept;
  Buffer(const Buffer&) = delete;
  Buffer& operator=(const Buffer&) = delete;
  ~Buffer();

  /// Replaces the contents (GL_STREAM_DRAW: written once a pass, read once).
  void upload(std::span<const std::byte> bytes);
  unsigned id() const { return id_; }

private:
  unsigned id_ = 0;
};

/// Move-only owner of a vertex array object.
class VertexArray {
public:
  VertexArray() = default;
  /// A new vertex array object. Throws GlError.
  static VertexArray create();
  VertexArray(VertexArray&& other) noexcept;
  VertexArray& operator=(VertexArray&& other) noexcept;
  VertexArray(const VertexArray&) = delete;
  VertexArray& operator=(const VertexArray&) = delete;
  ~VertexArray();

  void bind() const;
  unsigned id() const { return id_; }

private:
  unsigned id_ = 0;
};

/// Move-only owner of a sampler object: filtering and wrapping bound to a texture unit, over the
/// bound texture's own parameters.
class Sampler {
public:
  Sampler() = default;
  /// A repeat-wrapped sampler reading the nearest texel, or bilinearly. Throws GlError.
  static Sampler repeating(bool bilinear);
  Sampler(Sampler&& other) noexcept;
  Sampler& operator=(Sampler&& other) noexcept;
  Sampler(const Sampler&) = delete;
  Sampler& operator=(const Sampler&) = delete;
  ~Sampler();

  unsigned id() const { return id_; }

private:
  unsigned id_ = 0;
};

/// Draws fragment passes over lists of texel rectangles in one draw call each: the rectangles
/// go to a shader-storage buffer that rectsVertexShader() turns into two triangles apiece.
class RectPass {
public:
  /// Needs a current context. Throws GlError.
  RectPass();

  /// Runs the bound program over rects of a target of width × height texels (the viewport).
  void draw(std::span<const core::TexelRect> rects, int width, int height);
  /// The same for a program made with batchedRectsVertexShader(): rectangle k's fragments get
  /// dab dabOfRect[k]'s values.
  void draw(std::span<const core::TexelRect> rects, std::span<const int> dabOfRect, int width,
            int height);

private:
  Buffer rects_;
  VertexArray vertexArray_;
};

/// The vertex shader of RectPass programs: gl_FragCoord.xy of every fragment is a texel centre
/// inside one of the pass's rectangles.
const std::string& rectsVertexShader();
/// The same for a batch of dabs: each rectangle's dab's values (storage binding 1, nine vec4 and
/// an ivec4 a dab) as `flat out vec4 v_dab[9]` and `flat out ivec4 v_dabTexel`.
const std::string& batchedRectsVertexShader();

/// Move-only owner of a linked vertex + fragment program.
class Program {
public:
  Program() = default;
  /// Compiles and links. `name` (a file path, or a label for built-in shaders) prefixes every
  /// compiler message. Throws GlError with name, stage and the driver's log.
  Program(const std::string& name, const std::string& vertexSource,
          const std::string& fragmentSource);
  /// A compute program (GL 4.3) of one shader; errors as above.
  static Program compute(const std::string& name, const std::string& source);
  Program(Program&& other) noexcept;
  Program& operator=(Program&& other) noexcept;
  Program(const Program&) = delete;
  Program& operator=(const Program&) = delete;
  ~Program();

  void use() const;
  /// Location of a uniform, -1 when the program has none of that name.
  int uniform(const char* name) const;
  unsigned id() const { return id_; }

private:
  unsigned id_ = 0;
};

/// Draws one triangle covering the viewport (a fragment pass over every texel in the scissor).
void drawFullscreenPass();

/// The vertex shader every full-image pass uses: a triangle covering the viewport, with
/// v_uv in [0, 1].
const std::string& fullscreenVertexShader();

} // namespace octaclay::gpu
