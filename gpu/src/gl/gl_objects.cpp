#include "octaclay/gpu/gl_objects.h"

#include "half_float.h"

#include "octaclay/gpu/gl_error.h"

#include <epoxy/gl.h>

#include <bit>
#include <cstdint>
#include <utility>
#include <vector>

namespace octaclay::gpu {
namespace {

struct FormatInfo {
  GLenum internal, layout;
};

FormatInfo info(TextureFormat format) {
  switch (format) {
  case TextureFormat::Rgba32f:
    return {GL_RGBA32F, GL_RGBA};
  case TextureFormat::Rgba16f:
    return {GL_RGBA16F, GL_RGBA};
  case TextureFormat::R32f:
    return {GL_R32F, GL_RED};
  case TextureFormat::Rgba8:
    return {GL_RGBA8, GL_RGBA};
  }
  return {GL_RGBA32F, GL_RGBA};
}

std::size_t texelCount(core::TexelRect r) {
  return static_cast<std::size_t>(r.width) * static_cast<std::size_t>(r.height);
}

} // namespace

namespace {

GLenum layoutOf(int channels) {
  switch (channels) {
  case 1:
    return GL_RED;
  case 3:
    return GL_RGB;
  case 4:
    return GL_RGBA;
  }
  throw GlError("texels of " + std::to_string(channels) + " channels are not supported");
}

} // namespace

Texture::Texture(int width, int height, TextureFormat format) : Texture(width, height, format, 1) {}

Texture Texture::withLevels(int width, int height, TextureFormat format, int levels) {
  return Texture(width, height, format, levels);
}

Texture::Texture(int width, int height, TextureFormat format, int levels)
    : width_(width), height_(height), format_(format) {
  if (width < 1 || height < 1 || levels < 1) throw GlError("texture size must be positive");
  glGenTextures(1, &id_);
  glBindTexture(GL_TEXTURE_2D, id_);
  glTexStorage2D(GL_TEXTURE_2D, levels, info(format).internal, width, height);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  checkGlError("allocating a " + std::to_string(width) + "x" + std::to_string(height) + " texture");
}

Texture Texture::adopt(unsigned id, int width, int height, TextureFormat format) {
  Texture texture;
  texture.id_ = id;
  texture.width_ = width;
  texture.height_ = height;
  texture.format_ = format;
  return texture;
}

Texture Texture::wrap(unsigned id, int width, int height, TextureFormat format) {
  Texture texture = adopt(id, width, height, format);
  texture.owned_ = false;
  return texture;
}

Texture::Texture(Texture&& other) noexcept
    : id_(std::exchange(other.id_, 0)), owned_(other.owned_), width_(other.width_),
      height_(other.height_), format_(other.format_),
      framebuffer_(std::exchange(other.framebuffer_, 0)) {}

Texture& Texture::operator=(Texture&& other) noexcept {
  if (this != &other) {
    if (framebuffer_) glDeleteFramebuffers(1, &framebuffer_);
    if (id_ && owned_) glDeleteTextures(1, &id_);
    id_ = std::exchange(other.id_, 0);
    owned_ = other.owned_;
    framebuffer_ = std::exchange(other.framebuffer_, 0);
    width_ = other.width_;
    height_ = other.height_;
    format_ = other.format_;
  }
  return *this;
}

Texture::~Texture() {
  if (framebuffer_) glDeleteFramebuffers(1, &framebuffer_);
  if (id_ && owned_) glDeleteTextures(1, &id_);
}

unsigned Texture::release() {
  if (framebuffer_) glDeleteFramebuffers(1, &framebuffer_);
  framebuffer_ = 0;
  return std::exchange(id_, 0);
}

unsigned Texture::framebuffer() const {
  if (!framebuffer_) framebuffer_ = Framebuffer(*this).release();
  return framebuffer_;
}

void Texture::bindAsTarget() const {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer());
}

void Texture::fill(const std::array<float, 4>& value, core::TexelRect region) {
  GLint previous = 0;
  std::array<GLint, 4> box{};
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previous);
  glGetIntegerv(GL_SCISSOR_BOX, box.data());
  const bool scissor = glIsEnabled(GL_SCISSOR_TEST) == GL_TRUE;
  glEnable(GL_SCISSOR_TEST); // the clear writes the region only
  glScissor(region.x, region.y, region.width, region.height);
  bindAsTarget();
  glClearBufferfv(GL_COLOR, 0, value.data());
  glScissor(box[0], box[1], box[2], box[3]);
  if (!scissor) glDisable(GL_SCISSOR_TEST);
  glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(previous));
  checkGlError("filling a texture");
}

void Texture::upload(core::TexelRect region, std::span<const float> texels) {
  if (texels.size() != texelCount(region) * static_cast<std::size_t>(channels()))
    throw GlError("texture upload: " + std::to_string(texels.size()) + " floats for a " +
                  std::to_string(region.width) + "x" + std::to_string(region.height) + " region");
  uploadFrom(region, texels.data(), region.width, channels());
}

std::vector<float> Texture::read(core::TexelRect region) const {
  std::vector<float> texels(texelCount(region) * static_cast<std::size_t>(channels()));
  readInto(region, texels.data(), region.width, channels());
  return texels;
}

using detail::widenHalf;

void Texture::readInto(core::TexelRect region, float* out, int rowLength, int channels) const {
  const GLenum layout = layoutOf(channels);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer());
  if (format_ == TextureFormat::Rgba16f) {
    // Raw halves widened here: a software driver's generic half-to-float read path with
    // channel conversion costs several times this loop.
    thread_local std::vector<std::uint16_t> halves;
    thread_local std::vector<float> row;
    halves.resize(static_cast<std::size_t>(region.width) * region.height * 4);
    row.resize(static_cast<std::size_t>(region.width) * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 2);
    glPixelStorei(GL_PACK_ROW_LENGTH, 0);
    glReadPixels(region.x, region.y, region.width, region.height, GL_RGBA, GL_HALF_FLOAT,
                 halves.data());
    checkGlError("texture read-back");
    for (int y = 0; y < region.height; ++y) {
      const std::uint16_t* from = halves.data() + static_cast<std::size_t>(y) * region.width * 4;
      float* to = out + static_cast<std::size_t>(y) * rowLength * channels;
      float* widened = channels == 4 ? to : row.data();
      for (int k = 0; k < region.width * 4; ++k)
        widened[k] = widenHalf(from[k]);
      if (channels != 4)
        for (int x = 0; x < region.width; ++x)
          for (int c = 0; c < channels; ++c)
            to[x * channels + c] = row[static_cast<std::size_t>(x) * 4 + c];
    }
    return;
  }
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glPixelStorei(GL_PACK_ROW_LENGTH, rowLength);
  glReadPixels(region.x, region.y, region.width, region.height, layout, GL_FLOAT, out);
  glPixelStorei(GL_PACK_ROW_LENGTH, 0);
  checkGlError("texture read-back");
}

std::size_t Texture::packedTexelBytes() const {
  switch (format_) {
  case TextureFormat::Rgba32f:
    return 16;
  case TextureFormat::Rgba16f:
    return 8;
  case TextureFormat::R32f:
  case TextureFormat::Rgba8:
    return 4;
  }
  return 16;
}

void Texture::readToPackBuffer(core::TexelRect region, unsigned buffer, std::size_t offset) const {
  // Straight from the texture where the driver can (GL 4.5): a framebuffer made for a texture
  // costs a real GPU's driver more than the read (some 20 ms for a new undo pool page on an
  // H200, in perf), and the undo pool reads each of its pages once.
  static const bool direct =
      epoxy_gl_version() >= 45 || epoxy_has_gl_extension("GL_ARB_get_texture_sub_image");
  glBindBuffer(GL_PIXEL_PACK_BUFFER, buffer);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glPixelStorei(GL_PACK_ROW_LENGTH, 0);
  const FormatInfo f = info(format_);
  const GLenum type = format_ == TextureFormat::Rgba16f ? GL_HALF_FLOAT
                      : format_ == TextureFormat::Rgba8 ? GL_UNSIGNED_BYTE
                                                        : GL_FLOAT;
  void* at = reinterpret_cast<void*>(static_cast<std::uintptr_t>(offset));
  if (direct) {
    const std::size_t bytes = texelCount(region) * packedTexelBytes();
    glGetTextureSubImage(id_, 0, region.x, region.y, 0, region.width, region.height, 1, f.layout,
                         type, static_cast<GLsizei>(bytes), at);
  } else {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer());
    glReadPixels(region.x, region.y, region.width, region.height, f.layout, type, at);
  }
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  checkGlError("texture read into a pack buffer");
}

void Texture::uploadFrom(core::TexelRect region, const float* in, int rowLength, int channels) {
  const GLenum layout = layoutOf(channels);
  glBindTexture(GL_TEXTURE_2D, id_);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, rowLength);
  glTexSubImage2D(GL_TEXTURE_2D, 0, region.x, region.y, region.width, region.height, layout,
                  GL_FLOAT, in);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  checkGlError("texture upload");
}

Framebuffer::Framebuffer(const Texture& target) {
  glGenFramebuffers(1, &id_);
  glBindFramebuffer(GL_FRAMEBUFFER, id_);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target.id(), 0);
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    glDeleteFramebuffers(1, &id_);
    id_ = 0;
    throw GlError("framebuffer incomplete (status 0x" + std::to_string(status) + ")");
  }
}

Framebuffer::Framebuffer(Framebuffer&& other) noexcept : id_(std::exchange(other.id_, 0)) {}

Framebuffer& Framebuffer::operator=(Framebuffer&& other) noexcept {
  if (this != &other) {
    if (id_) glDeleteFramebuffers(1, &id_);
    id_ = std::exchange(other.id_, 0);
  }
  return *this;
}

Framebuffer::~Framebuffer() {
  if (id_) glDeleteFramebuffers(1, &id_);
}

unsigned Framebuffer::release() {
  return std::exchange(id_, 0);
}

void Framebuffer::bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, id_);
}

Buffer Buffer::create() {
  Buffer buffer;
  glGenBuffers(1, &buffer.id_);
  checkGlError("creating a buffer");
  return buffer;
}

Buffer::Buffer(Buffer&& other) noexcept : id_(std::exchange(other.id_, 0)) {}

Buffer& Buffer::operator=(Buffer&& other) noexcept {
  if (this != &other) {
    if (id_) glDeleteBuffers(1, &id_);
    id_ = std::exchange(other.id_, 0);
  }
  return *this;
}

Buffer::~Buffer() {
  if (id_) glDeleteBuffers(1, &id_);
}

void Buffer::upload(std::span<const std::byte> bytes) {
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, id_);
  glBufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(bytes.size()), bytes.data(),
               GL_STREAM_DRAW);
  checkGlError("buffer upload");
}

VertexArray VertexArray::create() {
  VertexArray array;
  glGenVertexArrays(1, &array.id_);
  checkGlError("creating a vertex array");
  return array;
}

VertexArray::VertexArray(VertexArray&& other) noexcept : id_(std::exchange(other.id_, 0)) {}

VertexArray& VertexArray::operator=(VertexArray&& other) noexcept {
  if (this != &other) {
    if (id_) glDeleteVertexArrays(1, &id_);
    id_ = std::exchange(other.id_, 0);
  }
  return *this;
}

VertexArray::~VertexArray() {
  if (id_) glDeleteVertexArrays(1, &id_);
}

void VertexArray::bind() const {
  glBindVertexArray(id_);
}

Sampler Sampler::repeating(bool bilinear) {
  Sampler sampler;
  glGenSamplers(1, &sampler.id_);
  const GLint filter = bilinear ? GL_LINEAR : GL_NEAREST;
  glSamplerParameteri(sampler.id_, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glSamplerParameteri(sampler.id_, GL_TEXTURE_WRAP_T, GL_REPEAT);
  glSamplerParameteri(sampler.id_, GL_TEXTURE_MIN_FILTER, filter);
  glSamplerParameteri(sampler.id_, GL_TEXTURE_MAG_FILTER, filter);
  checkGlError("creating a sampler");
  return sampler;
}

Sampler::Sampler(Sampler&& other) noexcept : id_(std::exchange(other.id_, 0)) {}

Sampler& Sampler::operator=(Sampler&& other) noexcept {
  if (this != &other) {
    if (id_) glDeleteSamplers(1, &id_);
    id_ = std::exchange(other.id_, 0);
  }
  return *this;
}

Sampler::~Sampler() {
  if (id_) glDeleteSamplers(1, &id_);
}

} // namespace octaclay::gpu
