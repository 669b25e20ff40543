// ShaderProgram: GLSL program loaded from <dir>/<name>.vert and .frag, written once for every platform:
// the files carry no #version line, and the loader puts shaderHeader() first (GLSL 3.30 core on the
// desktop, GLSL ES 3.00 with precision statements in the browser). Sources may use `#include "file.glsl"` (resolved relative to the shader directory). Compile and link
// logs are rewritten from the driver's `0:12(3): error: ...` to `path/to/file.frag:12: error: ...`.
#pragma once

#include <glm/glm.hpp>
#include "graphics/gl.h"

#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

namespace pba::graphics {

class ShaderProgram {
 public:
  /// Loads <dir>/<name>.vert + .frag. nullptr + *error on failure; the
  /// compiler log (with file paths and lines) is also printed to stderr.
  static std::unique_ptr<ShaderProgram> load(const std::string& dir, const std::string& name, std::string* error);
  /// Explicit files. Lets two programs share a fragment shader.
  static std::unique_ptr<ShaderProgram> loadFiles(const std::string& vertexPath, const std::string& fragmentPath,
                                                  std::string* error);
  ~ShaderProgram();
  ShaderProgram(const ShaderProgram&) = delete;
  ShaderProgram& operator=(const ShaderProgram&) = delete;

  void use() const;
  GLuint id() const { return program_; }
  const std::string& name() const { return name_; }

  /// Cached glGetUniformLocation; -1 (silently ignored by the setters) when the uniform is unused.
  GLint location(const std::string& uniform) const;
  void set(const std::string& uniform, int value) const;
  void set(const std::string& uniform, float value) const;
  void set(const std::string& uniform, const glm::vec2& value) const;
  void set(const std::string& uniform, const glm::vec3& value) const;
  void set(const std::string& uniform, const glm::vec4& value) const;
  void set(const std::string& uniform, const glm::mat3& value) const;
  void set(const std::string& uniform, const glm::mat4& value) const;
  void set(const std::string& uniform, const std::vector<glm::mat4>& values) const;  ///< mat4 array

 private:
  ShaderProgram() = default;
  GLuint program_ = 0;
  std::string name_;
  mutable std::unordered_map<std::string, GLint> locations_;
};

/// Rewrites a driver log: each `S:N(C): msg`, `S(N) : msg` or `ERROR: S:N: msg` line becomes
/// `files[N / 100000]:(N % 100000): msg` (preprocessShaderFile encodes the file in the line number).
std::string mapShaderLog(const std::string& log, const std::vector<std::string>& files);

/// The `#version` line (and, for GLSL ES, the default precisions) that every shader gets first.
const char* shaderHeader();

/// Reads `path`, puts shaderHeader() first unless the file has its own #version, and expands `#include "x"` lines recursively, emitting `#line k*100000+L` directives
/// where k indexes `files` (files[0] is `path`). Returns false + *error on a missing file.
bool preprocessShaderFile(const std::string& path, std::vector<std::string>& files, std::string* source,
                          std::string* error);

}  // namespace pba::graphics
