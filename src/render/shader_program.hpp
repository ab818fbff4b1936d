#pragma once
// GLSL programs loaded from files in shaders/ (never pasted into C++ strings).
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "render/gl.hpp"

namespace epviz::render {

// Where shader files are looked for, in order: `shaders/` next to the running
// binary, $EPVIZ_SHADER_DIR, then shaders/ in each of data_search_path().
std::vector<std::filesystem::path> shader_search_path();

// The first directory of shader_search_path() holding `file_name`; throws
// std::runtime_error listing every place searched.
std::filesystem::path find_shader_file(std::string_view file_name);

class ShaderProgram {
 public:
  // Compiles and links the named files (geometry may be empty). Throws
  // std::runtime_error with the file name and the GL info log on failure.
  static ShaderProgram from_files(std::string_view vertex_file, std::string_view fragment_file,
                                  std::string_view geometry_file = {});

  ShaderProgram() = default;
  ~ShaderProgram();
  ShaderProgram(ShaderProgram&& other) noexcept;
  ShaderProgram& operator=(ShaderProgram&& other) noexcept;
  ShaderProgram(const ShaderProgram&) = delete;
  ShaderProgram& operator=(const ShaderProgram&) = delete;

  GLuint id() const { return id_; }
  void use() const { glUseProgram(id_); }
  // -1 when the uniform does not exist or was optimised away (GL ignores sets to -1).
  GLint uniform_location(const char* name) const { return glGetUniformLocation(id_, name); }

  // Setters act on the program in use; call use() first.
  void set(const char* name, int value) const;
  void set(const char* name, float value) const;
  void set(const char* name, const glm::vec2& value) const;
  void set(const char* name, const glm::vec3& value) const;
  void set(const char* name, const glm::vec4& value) const;
  void set(const char* name, const glm::mat3& value) const;
  void set(const char* name, const glm::mat4& value) const;

 private:
  explicit ShaderProgram(GLuint id) : id_(id) {}
  GLuint id_ = 0;
};

}  // namespace epviz::render
