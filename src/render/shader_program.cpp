#include "render/shader_program.hpp"

#include "io/data_dir.hpp"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <system_error>
#include <utility>

#include <glm/gtc/type_ptr.hpp>

namespace epviz::render {
namespace {

std::filesystem::path executable_directory() {
  std::error_code error;
  const auto exe = std::filesystem::read_symlink("/proc/self/exe", error);
  if (error) return {};
  return exe.parent_path();
}

std::string read_text_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read shader file '" + path.string() + "'");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string shader_info_log(GLuint shader) {
  GLint length = 0;
  glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
  glGetShaderInfoLog(shader, length, nullptr, log.data());
  return log.c_str();
}

std::string program_info_log(GLuint program) {
  GLint length = 0;
  glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
  glGetProgramInfoLog(program, length, nullptr, log.data());
  return log.c_str();
}

GLuint compile_shader_file(GLenum stage, std::string_view file_name) {
  const auto path = find_shader_file(file_name);
  const std::string source = read_text_file(path);
  const GLuint shader = glCreateShader(stage);
  const char* text = source.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    const std::string log = shader_info_log(shader);
    glDeleteShader(shader);
    throw std::runtime_error("cannot compile shader '" + path.string() + "':\n" + log);
  }
  return shader;
}

}  // namespace

std::vector<std::filesystem::path> shader_search_path() {
  std::vector<std::filesystem::path> path;
  if (auto dir = executable_directory(); !dir.empty()) path.push_back(dir / "shaders");
  if (const char* env = std::getenv("EPVIZ_SHADER_DIR"); env != nullptr && *env != '\0')
    path.emplace_back(env);
  for (const auto& dir : io::data_search_path()) path.push_back(dir / "shaders");
  return path;
}

std::filesystem::path find_shader_file(std::string_view file_name) {
  std::string searched;
  for (const auto& dir : shader_search_path()) {
    const auto candidate = dir / file_name;
    std::error_code error;
    if (std::filesystem::is_regular_file(candidate, error)) return candidate;
    searched += "\n  " + dir.string();
  }
  throw std::runtime_error("shader file '" + std::string(file_name) +
                           "' not found; searched:" + searched +
                           "\n(set EPVIZ_DATA_DIR to a folder holding shaders/, or "
                           "EPVIZ_SHADER_DIR to the shaders folder)");
}

ShaderProgram ShaderProgram::from_files(std::string_view vertex_file,
                                        std::string_view fragment_file,
                                        std::string_view geometry_file) {
  std::vector<GLuint> shaders;
  auto release = [&] {
    for (GLuint shader : shaders) glDeleteShader(shader);
  };
  try {
    shaders.push_back(compile_shader_file(GL_VERTEX_SHADER, vertex_file));
    if (!geometry_file.empty())
      shaders.push_back(compile_shader_file(GL_GEOMETRY_SHADER, geometry_file));
    shaders.push_back(compile_shader_file(GL_FRAGMENT_SHADER, fragment_file));
  } catch (...) {
    release();
    throw;
  }
  const GLuint program = glCreateProgram();
  for (GLuint shader : shaders) glAttachShader(program, shader);
  glLinkProgram(program);
  release();  // the program keeps what it needs
  GLint ok = GL_FALSE;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    const std::string log = program_info_log(program);
    glDeleteProgram(program);
    std::string names = std::string(vertex_file) + ", " +
                        (geometry_file.empty() ? "" : std::string(geometry_file) + ", ") +
                        std::string(fragment_file);
    throw std::runtime_error("cannot link shader program (" + names + "):\n" + log);
  }
  return ShaderProgram(program);
}

ShaderProgram::~ShaderProgram() {
  if (id_ != 0) glDeleteProgram(id_);
}

ShaderProgram::ShaderProgram(ShaderProgram&& other) noexcept : id_(std::exchange(other.id_, 0)) {}

ShaderProgram& ShaderProgram::operator=(ShaderProgram&& other) noexcept {
  if (this != &other) {
    if (id_ != 0) glDeleteProgram(id_);
    id_ = std::exchange(other.id_, 0);
  }
  return *this;
}

void ShaderProgram::set(const char* name, int value) const {
  glUniform1i(uniform_location(name), value);
}
void ShaderProgram::set(const char* name, float value) const {
  glUniform1f(uniform_location(name), value);
}
void ShaderProgram::set(const char* name, const glm::vec2& value) const {
  glUniform2fv(uniform_location(name), 1, glm::value_ptr(value));
}
void ShaderProgram::set(const char* name, const glm::vec3& value) const {
  glUniform3fv(uniform_location(name), 1, glm::value_ptr(value));
}
void ShaderProgram::set(const char* name, const glm::vec4& value) const {
  glUniform4fv(uniform_location(name), 1, glm::value_ptr(value));
}
void ShaderProgram::set(const char* name, const glm::mat3& value) const {
  glUniformMatrix3fv(uniform_location(name), 1, GL_FALSE, glm::value_ptr(value));
}
void ShaderProgram::set(const char* name, const glm::mat4& value) const {
  glUniformMatrix4fv(uniform_location(name), 1, GL_FALSE, glm::value_ptr(value));
}

}  // namespace epviz::render
