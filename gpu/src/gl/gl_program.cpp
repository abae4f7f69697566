// Program: compiling and linking a vertex + fragment pair (or one compute shader), with the
// driver's log in the error.
#include "octaclay/gpu/gl_error.h"
#include "octaclay/gpu/gl_objects.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <string>
#include <utility>

namespace octaclay::gpu {
namespace {

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
  throw GlError(name + ": " +
                (stage == GL_VERTEX_SHADER    ? "vertex"
                 : stage == GL_COMPUTE_SHADER ? "compute"
                                              : "fragment") +
                " shader does not compile:\n" + log);
}

} // namespace

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

Program Program::compute(const std::string& name, const std::string& source) {
  const GLuint shader = compileStage(name, GL_COMPUTE_SHADER, source);
  Program program;
  program.id_ = glCreateProgram();
  glAttachShader(program.id_, shader);
  glLinkProgram(program.id_);
  glDeleteShader(shader);
  GLint ok = GL_FALSE;
  glGetProgramiv(program.id_, GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    GLint length = 0;
    glGetProgramiv(program.id_, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
    glGetProgramInfoLog(program.id_, length, nullptr, log.data());
    throw GlError(name + ": program does not link:\n" + log);
  }
  return program;
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

} // namespace octaclay::gpu
