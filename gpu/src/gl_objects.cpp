#include "octaclay/gpu/gl_objects.h"

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

GLuint compileStage(const std::string& name, GLenum stage, const std::string& source) {
  const GLuint shader = glCreateShader(stage);
  const char* text = source.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok == GL_TRUE) return shader;
  GLint length = 0;
  glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
  glGetShaderInfoLog(shader, length, nullptr, log.data());
  glDeleteShader(shader);
  while (!log.empty() && (log.back() == '\0' || log.back() == '\n'))
    log.pop_back();
  throw GlError(name + ": " + (stage == GL_VERTEX_SHADER ? "vertex" : "fragment") +
                " shader does not compile:\n" + log);
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

Texture Texture::wrap(unsigned id, int width, int height, TextureFormat format) {
  Texture texture;
  texture.id_ = id;
  texture.width_ = width;
  texture.height_ = height;
  texture.format_ = format;
  return texture;
}

Texture::Texture(Texture&& other) noexcept
    : id_(std::exchange(other.id_, 0)), width_(other.width_), height_(other.height_),
      format_(other.format_), framebuffer_(std::exchange(other.framebuffer_, 0)) {}

Texture& Texture::operator=(Texture&& other) noexcept {
  if (this != &other) {
    if (framebuffer_) glDeleteFramebuffers(1, &framebuffer_);
    if (id_) glDeleteTextures(1, &id_);
    id_ = std::exchange(other.id_, 0);
    framebuffer_ = std::exchange(other.framebuffer_, 0);
    width_ = other.width_;
    height_ = other.height_;
    format_ = other.format_;
  }
  return *this;
}

Texture::~Texture() {
  if (framebuffer_) glDeleteFramebuffers(1, &framebuffer_);
  if (id_) glDeleteTextures(1, &id_);
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

namespace {

// Exact half → float without branches, so the compiler vectorizes a row of them: the half's
// exponent and mantissa moved into a float's and scaled by 2^112 (subnormal halves become
// subnormal floats and scale exactly too); infinities and NaNs keep the all-ones exponent.
float widenHalf(std::uint16_t h) {
  const std::uint32_t magnitude = h & 0x7fffu;
  const float scaled = std::bit_cast<float>(magnitude << 13) * 0x1p112f;
  const std::uint32_t special = 0u - static_cast<std::uint32_t>(magnitude >= 0x7c00u);
  const std::uint32_t bits = (((magnitude << 13) | 0x7f800000u) & special) |
                             (std::bit_cast<std::uint32_t>(scaled) & ~special);
  return std::bit_cast<float>(bits | (static_cast<std::uint32_t>(h & 0x8000u) << 16));
}

} // namespace

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

Program::Program(const std::string& name, const std::string& vertexSource,
                 const std::string& fragmentSource) {
  const GLuint vertex = compileStage(name, GL_VERTEX_SHADER, vertexSource);
  GLuint fragment = 0;
  try {
    fragment = compileStage(name, GL_FRAGMENT_SHADER, fragmentSource);
  } catch (...) {
    glDeleteShader(vertex);
    throw;
  }
  id_ = glCreateProgram();
  glAttachShader(id_, vertex);
  glAttachShader(id_, fragment);
  glLinkProgram(id_);
  glDeleteShader(vertex);
  glDeleteShader(fragment);
  GLint ok = GL_FALSE;
  glGetProgramiv(id_, GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    GLint length = 0;
    glGetProgramiv(id_, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
    glGetProgramInfoLog(id_, length, nullptr, log.data());
    glDeleteProgram(id_);
    id_ = 0;
    throw GlError(name + ": program does not link:\n" + log);
  }
}

Program::Program(Program&& other) noexcept : id_(std::exchange(other.id_, 0)) {}

Program& Program::operator=(Program&& other) noexcept {
  if (this != &other) {
    if (id_) glDeleteProgram(id_);
    id_ = std::exchange(other.id_, 0);
  }
  return *this;
}

Program::~Program() {
  if (id_) glDeleteProgram(id_);
}

void Program::use() const {
  glUseProgram(id_);
}

int Program::uniform(const char* name) const {
  return glGetUniformLocation(id_, name);
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

RectPass::RectPass() : rects_(Buffer::create()) {
  glGenVertexArrays(1, &vertexArray_);
}

RectPass::RectPass(RectPass&& other) noexcept
    : rects_(std::move(other.rects_)), vertexArray_(std::exchange(other.vertexArray_, 0)) {}

RectPass& RectPass::operator=(RectPass&& other) noexcept {
  if (this != &other) {
    if (vertexArray_) glDeleteVertexArrays(1, &vertexArray_);
    rects_ = std::move(other.rects_);
    vertexArray_ = std::exchange(other.vertexArray_, 0);
  }
  return *this;
}

RectPass::~RectPass() {
  if (vertexArray_) glDeleteVertexArrays(1, &vertexArray_);
}

void RectPass::draw(std::span<const core::TexelRect> rects, int width, int height) {
  if (rects.empty()) return;
  std::vector<GLint> data{width, height, 0, 0};
  for (const core::TexelRect& r : rects)
    data.insert(data.end(), {r.x, r.y, r.width, r.height});
  rects_.upload(std::as_bytes(std::span(data)));
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, rects_.id());
  glBindVertexArray(vertexArray_);
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(6 * rects.size()));
  checkGlError("rectangle pass");
}

const std::string& rectsVertexShader() {
  static const std::string source = R"(#version 430 core
layout(std430, binding = 0) readonly buffer PassRects {
  ivec4 target; // width, height
  ivec4 rects[]; // x, y, width, height
};
void main() {
  ivec4 r = rects[gl_VertexID / 6];
  const ivec2 corners[6] = ivec2[6](ivec2(0, 0), ivec2(1, 0), ivec2(0, 1),
                                    ivec2(1, 0), ivec2(1, 1), ivec2(0, 1));
  vec2 p = vec2(r.xy + corners[gl_VertexID % 6] * r.zw) / vec2(target.xy);
  gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}
)";
  return source;
}

void drawFullscreenPass() {
  // Core profile needs a bound vertex array even when the vertex shader makes its own vertices.
  // Vertex arrays are not shared between contexts: this assumes one engine context per process.
  static GLuint vertexArray = 0;
  if (!vertexArray) glGenVertexArrays(1, &vertexArray);
  glBindVertexArray(vertexArray);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  checkGlError("full-screen pass");
}

const std::string& fullscreenVertexShader() {
  static const std::string source = R"(#version 430 core
out vec2 v_uv;
void main() {
  vec2 corner = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
  v_uv = corner;
  gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
)";
  return source;
}

} // namespace octaclay::gpu
