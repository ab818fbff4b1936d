#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "render/render_test_support.hpp"
#include "render/shader_program.hpp"
#include "support/errors.hpp"
#include "support/temp_dir.hpp"

namespace {

namespace fs = std::filesystem;
using epviz::render::ShaderProgram;

// Writes shader files into a fresh directory and points EPVIZ_SHADER_DIR at it.
class ShaderDirectory : public epviz::test::TempDirTest {
 protected:
  void SetUp() override {
    epviz::testing::shared_gl_context();
    setenv("EPVIZ_SHADER_DIR", dir_.c_str(), 1);
  }
  void TearDown() override { unsetenv("EPVIZ_SHADER_DIR"); }
};

TEST_F(ShaderDirectory, ProjectShadersCompileAndLink) {
  EXPECT_NE(ShaderProgram::from_files("mesh.vert", "mesh.frag").id(), 0u);
  EXPECT_NE(ShaderProgram::from_files("line.vert", "line.frag", "line.geom").id(), 0u);
}

TEST_F(ShaderDirectory, CompileErrorNamesTheFileAndCarriesTheLog) {
  tmp_.write("broken_test.vert",
             "#version 330 core\nvoid main() { gl_Position = vec4(undeclared_thing); }\n");
  const auto message = epviz::test::error_of<std::runtime_error>(
      [] { ShaderProgram::from_files("broken_test.vert", "solid.frag"); });
  EXPECT_NE(message.find("broken_test.vert"), std::string::npos) << message;
  EXPECT_NE(message.find("undeclared_thing"), std::string::npos) << message;
}

TEST_F(ShaderDirectory, LinkErrorNamesTheFiles) {
  // The vertex shader calls a function that no stage defines: compiles, cannot link.
  tmp_.write("link_a.vert",
             "#version 330 core\nfloat helper();\nvoid main() { gl_Position = vec4(helper()); }\n");
  tmp_.write("link_b.frag", "#version 330 core\nout vec4 c;\nvoid main() { c = vec4(1.0); }\n");
  const auto message = epviz::test::error_of<std::runtime_error>(
      [] { ShaderProgram::from_files("link_a.vert", "link_b.frag"); });
  EXPECT_NE(message.find("link_a.vert"), std::string::npos) << message;
  EXPECT_NE(message.find("link_b.frag"), std::string::npos) << message;
}

TEST_F(ShaderDirectory, MissingFileListsWhereItLooked) {
  const auto message = epviz::test::error_of<std::runtime_error>(
      [] { ShaderProgram::from_files("no_such_shader.vert", "solid.frag"); });
  EXPECT_NE(message.find("no_such_shader.vert"), std::string::npos) << message;
  EXPECT_NE(message.find(dir_.string()), std::string::npos) << message;
}

}  // namespace
