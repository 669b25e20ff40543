// ShaderProgram: file loading with #include, compile/link with logs mapped to file:line, uniforms.
#include "graphics/shader.h"

#include <glm/gtc/type_ptr.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

namespace pba::graphics {
namespace {

// Drivers disagree on the source-string number of `#line L S` (Mesa reports 0 for every file), so
// the file is encoded in the line number itself: file k's line L is reported as k * kLineStride + L.
constexpr int kLineStride = 100000;

std::string lineDirective(int fileIndex, int line) {
  return "#line " + std::to_string(fileIndex * kLineStride + line) + "\n";
}

/// `#include "name"` (spaces allowed around '#') -> name; empty when the line is not an include.
std::string includedName(const std::string& line) {
  std::size_t i = line.find_first_not_of(" \t");
  if (i == std::string::npos || line[i] != '#') return "";
  i = line.find_first_not_of(" \t", i + 1);
  if (i == std::string::npos || line.compare(i, 7, "include") != 0) return "";
  const std::size_t open = line.find('"', i + 7);
  const std::size_t close = open == std::string::npos ? open : line.find('"', open + 1);
  if (close == std::string::npos) return "";
  return line.substr(open + 1, close - open - 1);
}

bool readText(const std::string& path, std::string* text) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::ostringstream buffer;
  buffer << in.rdbuf();
  *text = buffer.str();
  return true;
}

bool expand(const std::string& path, int depth, std::vector<std::string>& files, std::string* out, std::string* error) {
  if (depth > 8) {
    if (error) *error = path + ": #include nested too deeply (cycle?)";
    return false;
  }
  std::string text;
  if (!readText(path, &text)) {
    if (error) *error = path + ": cannot open shader file";
    return false;
  }
  const int fileIndex = static_cast<int>(files.size());
  files.push_back(path);
  if (depth > 0) *out += lineDirective(fileIndex, 1);  // included files have no #version
  // The top file gets the platform's #version header unless it names its own.
  if (depth == 0 && text.find("#version") == std::string::npos) {
    *out += shaderHeader();
    *out += lineDirective(fileIndex, 1);
  }
  const std::filesystem::path dir = std::filesystem::path(path).parent_path();
  std::istringstream lines(text);
  std::string line;
  int lineNumber = 0;
  bool afterVersion = false;
  while (std::getline(lines, line)) {
    ++lineNumber;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const std::string name = includedName(line);
    if (!name.empty()) {
      const std::string included = (dir / name).string();
      if (!expand(included, depth + 1, files, out, error)) {
        if (error) *error = path + ":" + std::to_string(lineNumber) + ": " + *error;
        return false;
      }
      *out += lineDirective(fileIndex, lineNumber + 1);
      continue;
    }
    *out += line + "\n";
    // `#line` may not precede `#version`; number the top file from just after it.
    if (!afterVersion && line.find("#version") != std::string::npos) {
      afterVersion = true;
      *out += lineDirective(fileIndex, lineNumber + 1);
    }
  }
  return true;
}

GLuint compile(GLenum stage, const std::string& path, std::string* error) {
  std::vector<std::string> files;
  std::string source;
  if (!preprocessShaderFile(path, files, &source, error)) return 0;
  const GLuint shader = glCreateShader(stage);
  const char* text = source.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  GLint length = 0;
  glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<std::size_t>(length > 0 ? length : 0), '\0');
  if (length > 0) glGetShaderInfoLog(shader, length, nullptr, log.data());
  const std::string mapped = mapShaderLog(log.c_str(), files);
  if (!ok) {
    std::cerr << mapped;
    if (error) {
      const std::size_t end = mapped.find('\n');
      *error = "shader compile failed: " + (mapped.empty() ? path : mapped.substr(0, end));
    }
    glDeleteShader(shader);
    return 0;
  }
  return shader;
}

}  // namespace

const char* shaderHeader() {
#ifdef __EMSCRIPTEN__
  // WebGL2: GLSL ES 3.00 has no default float precision in fragment shaders and lowp samplers.
  return "#version 300 es\n"
         "precision highp float;\n"
         "precision highp int;\n"
         "precision highp sampler2D;\n"
         "precision highp sampler2DShadow;\n";
#else
  return "#version 330 core\n";
#endif
}

bool preprocessShaderFile(const std::string& path, std::vector<std::string>& files, std::string* source,
                          std::string* error) {
  source->clear();
  files.clear();
  return expand(path, 0, files, source, error);
}

std::string mapShaderLog(const std::string& log, const std::vector<std::string>& files) {
  // Mesa: "0:12(3): error: msg"; NVIDIA: "0(12) : error C0000: msg"; AMD/Intel: "ERROR: 0:12: msg".
  auto location = [&](long line) {
    const auto file = static_cast<std::size_t>(line / kLineStride);
    const std::string name = file < files.size() ? files[file] : "<source " + std::to_string(file) + ">";
    return name + ":" + std::to_string(line % kLineStride);
  };
  std::istringstream lines(log);
  std::string line;
  std::string out;
  while (std::getline(lines, line)) {
    if (line.empty()) continue;
    long source = 0, number = 0, column = 0;
    int used = 0;
    char kind[8] = {0};
    if (std::sscanf(line.c_str(), "%ld:%ld(%ld): %n", &source, &number, &column, &used) == 3 && used > 0) {
      out += location(number) + ": " + line.substr(static_cast<std::size_t>(used)) + "\n";
    } else if (used = 0; std::sscanf(line.c_str(), "%ld(%ld) : %n", &source, &number, &used) == 2 && used > 0) {
      out += location(number) + ": " + line.substr(static_cast<std::size_t>(used)) + "\n";
    } else if (used = 0;
               std::sscanf(line.c_str(), "%7[A-Z]: %ld:%ld: %n", kind, &source, &number, &used) == 3 && used > 0) {
      out += location(number) + ": " + kind + ": " + line.substr(static_cast<std::size_t>(used)) + "\n";
    } else {
      out += line + "\n";
    }
  }
  return out;
}

std::unique_ptr<ShaderProgram> ShaderProgram::load(const std::string& dir, const std::string& name,
                                                   std::string* error) {
  const std::string base = (std::filesystem::path(dir) / name).string();
  return loadFiles(base + ".vert", base + ".frag", error);
}

std::unique_ptr<ShaderProgram> ShaderProgram::loadFiles(const std::string& vertexPath, const std::string& fragmentPath,
                                                        std::string* error) {
  struct Stage {
    GLenum type;
    const std::string* path;
  };
  const Stage stages[] = {{GL_VERTEX_SHADER, &vertexPath}, {GL_FRAGMENT_SHADER, &fragmentPath}};
  std::vector<GLuint> shaders;
  auto cleanup = [&] {
    for (GLuint s : shaders) glDeleteShader(s);
  };
  for (const Stage& stage : stages) {
    const GLuint shader = compile(stage.type, *stage.path, error);
    if (!shader) {
      cleanup();
      return nullptr;
    }
    shaders.push_back(shader);
  }
  std::unique_ptr<ShaderProgram> program(new ShaderProgram());
  program->name_ = std::filesystem::path(vertexPath).stem().string();
  program->program_ = glCreateProgram();
  for (GLuint s : shaders) glAttachShader(program->program_, s);
  glLinkProgram(program->program_);
  cleanup();
  GLint ok = GL_FALSE;
  glGetProgramiv(program->program_, GL_LINK_STATUS, &ok);
  if (!ok) {
    GLint length = 0;
    glGetProgramiv(program->program_, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<std::size_t>(length > 0 ? length : 0), '\0');
    if (length > 0) glGetProgramInfoLog(program->program_, length, nullptr, log.data());
    std::cerr << vertexPath << " + " << fragmentPath << ": link error:\n" << log.c_str() << "\n";
    if (error) *error = "shader link failed (" + vertexPath + " + " + fragmentPath + "): " + log.c_str();
    return nullptr;
  }
  return program;
}

ShaderProgram::~ShaderProgram() {
  if (program_) glDeleteProgram(program_);
}

void ShaderProgram::use() const { glUseProgram(program_); }

GLint ShaderProgram::location(const std::string& uniform) const {
  const auto found = locations_.find(uniform);
  if (found != locations_.end()) return found->second;
  const GLint loc = glGetUniformLocation(program_, uniform.c_str());
  locations_.emplace(uniform, loc);
  return loc;
}

void ShaderProgram::set(const std::string& u, int v) const { glUniform1i(location(u), v); }
void ShaderProgram::set(const std::string& u, float v) const { glUniform1f(location(u), v); }
void ShaderProgram::set(const std::string& u, const glm::vec2& v) const {
  glUniform2fv(location(u), 1, glm::value_ptr(v));
}
void ShaderProgram::set(const std::string& u, const glm::vec3& v) const {
  glUniform3fv(location(u), 1, glm::value_ptr(v));
}
void ShaderProgram::set(const std::string& u, const glm::vec4& v) const {
  glUniform4fv(location(u), 1, glm::value_ptr(v));
}
void ShaderProgram::set(const std::string& u, const glm::mat3& v) const {
  glUniformMatrix3fv(location(u), 1, GL_FALSE, glm::value_ptr(v));
}
void ShaderProgram::set(const std::string& u, const glm::mat4& v) const {
  glUniformMatrix4fv(location(u), 1, GL_FALSE, glm::value_ptr(v));
}
void ShaderProgram::set(const std::string& u, const std::vector<glm::mat4>& v) const {
  if (!v.empty()) glUniformMatrix4fv(location(u), static_cast<GLsizei>(v.size()), GL_FALSE, glm::value_ptr(v[0]));
}

}  // namespace pba::graphics
