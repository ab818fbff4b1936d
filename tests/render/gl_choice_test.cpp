// The backend a command draws with: --gl over EPVIZ_GL over "auto", and an
// unknown name refused naming where it came from and what is allowed.
#include <gtest/gtest.h>

#include <cstdlib>
#include <optional>
#include <string>

#include "io/bad_input.hpp"
#include "render/gl_choice.hpp"

namespace {

using epviz::render::GlChoice;

// Sets EPVIZ_GL for one test and puts back what was there.
class ScopedGlVariable {
 public:
  explicit ScopedGlVariable(const char* value) {
    if (const char* old = std::getenv("EPVIZ_GL")) old_ = old;
    if (value)
      ::setenv("EPVIZ_GL", value, 1);
    else
      ::unsetenv("EPVIZ_GL");
  }
  ~ScopedGlVariable() {
    if (old_)
      ::setenv("EPVIZ_GL", old_->c_str(), 1);
    else
      ::unsetenv("EPVIZ_GL");
  }

 private:
  std::optional<std::string> old_;
};

std::string refusal(const std::string& option) {
  try {
    (void)GlChoice(option);
  } catch (const epviz::io::BadInput& e) {
    return e.what();
  }
  return "no refusal";
}

TEST(GlChoice, OptionOverEnvironmentOverAuto) {
  {
    const ScopedGlVariable unset(nullptr);
    EXPECT_EQ(GlChoice("").backend(), "auto");
    EXPECT_EQ(GlChoice("osmesa").backend(), "osmesa");
  }
  const ScopedGlVariable osmesa("osmesa");
  EXPECT_EQ(GlChoice("").backend(), "osmesa");
  EXPECT_EQ(GlChoice("egl").backend(), "egl");
}

TEST(GlChoice, UnknownNameIsBadInputNamingItsSource) {
  const ScopedGlVariable bogus("glx");
  EXPECT_EQ(refusal(""), "EPVIZ_GL: unknown GL backend 'glx' (allowed: auto, egl, osmesa)");
  EXPECT_EQ(refusal("vulkan"), "--gl: unknown GL backend 'vulkan' (allowed: auto, egl, osmesa)");
  // A value given on the command line is quoted on one line, whatever it holds.
  EXPECT_EQ(refusal("a\nb").find('\n'), std::string::npos);
}

}  // namespace
