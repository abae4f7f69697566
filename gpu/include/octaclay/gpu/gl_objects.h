#pragma once

#include <span>
#include <string>
#include <vector>

namespace octaclay::gpu {

/// Pixel formats of the images the engine keeps on the GPU.
enum class TextureFormat {
  Rgba32f, ///< positions (xyz) + saliency (w): float32 so edits round-trip bit-exactly
  Rgba16f, ///< diffuse colour
  R32f,    ///< single-channel float data
};

/// A rectangle of texels: origin (x, y), size (width, height).
struct Region {
  int x = 0, y = 0, width = 0, height = 0;
};

/// Move-only owner of a 2D texture. Can be empty, adopt a foreign id (wrap) and give it back
/// (release). All calls need the owning context current on the calling thread.
class Texture {
public:
  Texture() = default;
  /// Allocates width × height texels of format, nearest filtering, clamped. Throws GlError.
  Texture(int width, int height, TextureFormat format);
  static Texture wrap(unsigned id, int width, int height, TextureFormat format);
  Texture(Texture&& other) noexcept;
  Texture& operator=(Texture&& other) noexcept;
  Texture(const Texture&) = delete;
  Texture& operator=(const Texture&) = delete;
  ~Texture();

  /// Writes region from floats, channels-per-texel as the format has (4 or 1), row-major.
  void upload(Region region, std::span<const float> texels);
  /// Reads region back as floats, row-major.
  std::vector<float> read(Region region) const;

  unsigned id() const { return id_; }
  int width() const { return width_; }
  int height() const { return height_; }
  TextureFormat format() const { return format_; }
  int channels() const { return format_ == TextureFormat::R32f ? 1 : 4; }
  /// Gives up ownership and returns the id (the texture is empty after).
  unsigned release();

private:
  unsigned id_ = 0;
  int width_ = 0, height_ = 0;
  TextureFormat format_ = TextureFormat::Rgba32f;
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

private:
  unsigned id_ = 0;
};

/// Move-only owner of a linked vertex + fragment program.
class Program {
public:
  Program() = default;
  /// Compiles and links. `name` (a file path, or a label for built-in shaders) prefixes every
  /// compiler message. Throws GlError with name, stage and the driver's log.
  Program(const std::string& name, const std::string& vertexSource,
          const std::string& fragmentSource);
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
