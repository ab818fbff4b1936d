#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "render/render_test_support.hpp"
#include "render/shader_program.hpp"

namespace {

namespace fs = std::filesystem;
using epviz::render::ShaderProgram;

// Writes shader files into a fresh directory and points EPVIZ_SHADER_DIR at it.
class ShaderDirectory : public ::testing::Test {
 protected:
  void SetUp() override {
    epviz::testing::shared_gl_context();
    dir_ = fs::temp_directory_path() / ("epviz_shader_test_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    setenv("EPVIZ_SHADER_DIR", dir_.c_str(), 1);
  }
  void TearDown() override {
    unsetenv("EPVIZ_SHADER_DIR");
    fs::remove_all(dir_);
  }
  void write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
  }
  fs::path dir_;
};

TEST_F(ShaderDirectory, ProjectShadersCompileAndLink) {
  EXPECT_NE(ShaderProgram::from_files("mesh.vert", "mesh.frag").id(), 0u);
  EXPECT_NE(ShaderProgram::from_files("line.vert", "line.frag", "line.geom").id(), 0u);
}

TEST_F(ShaderDirectory, CompileErrorNamesTheFileAndCarriesTheLog) {
  write("broken_test.vert",
        "#version 330 core\nvoid main() { gl_Position = vec4(undeclared_thing); }\n");
  try {
    ShaderProgram::from_files("broken_test.vert", "solid.frag");
    FAIL() << "a broken shader must throw";
  } catch (const std::runtime_error& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("broken_test.vert"), std::string::npos) << message;
    EXPECT_NE(message.find("undeclared_thing"), std::string::npos) << message;
  }
}

TEST_F(ShaderDirectory, LinkErrorNamesTheFiles) {
  // The vertex shader calls a function that no stage defines: compiles, cannot link.
  write("link_a.vert",
        "#version 330 core\nfloat helper();\nvoid main() { gl_Position = vec4(helper()); }\n");
  write("link_b.frag", "#version 330 core\nout vec4 c;\nvoid main() { c = vec4(1.0); }\n");
  try {
    ShaderProgram::from_files("link_a.vert", "link_b.frag");
    FAIL() << "a program that cannot link must throw";
  } catch (const std::runtime_error& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("link_a.vert"), std::string::npos) << message;
    EXPECT_NE(message.find("link_b.frag"), std::string::npos) << message;
  }
}

TEST_F(ShaderDirectory, MissingFileListsWhereItLooked) {
  try {
    ShaderProgram::from_files("no_such_shader.vert", "solid.frag");
    FAIL() << "a missing shader must throw";
  } catch (const std::runtime_error& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("no_such_shader.vert"), std::string::npos) << message;
    EXPECT_NE(message.find(dir_.string()), std::string::npos) << message;
  }
}

}  // namespace
