// Forces the debug checks on, whatever the build type, to test the macro.
#define SDFWB_GL_DEBUG_CHECKS 1
#include "glcontext/gl_debug.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "gl_test_support.h"

using sdfwb::glcontext::checkGlError;
using sdfwb::glcontext::GlError;
using sdfwb::glcontext::glErrorName;
using ::testing::HasSubstr;
using ::testing::MatchesRegex;

namespace {

using GlDebugTest = sdfwb::test::GlTest;

constexpr GLenum kNotACapability = 0x1234;

TEST(GlErrorName, NamesKnownCodesAndPrintsOthersInHex) {
  EXPECT_EQ(glErrorName(GL_INVALID_ENUM), "GL_INVALID_ENUM");
  EXPECT_EQ(glErrorName(GL_INVALID_FRAMEBUFFER_OPERATION), "GL_INVALID_FRAMEBUFFER_OPERATION");
  EXPECT_EQ(glErrorName(0xBEEF), "0xBEEF");
}

TEST_F(GlDebugTest, CheckNamesTheErrorTheCallAndTheLocation) {
  gl().Enable(kNotACapability);
  try {
    checkGlError(gl(), "gl.Enable(kNotACapability)");
    FAIL() << "no error reported";
  } catch (const GlError& error) {
    EXPECT_THAT(error.what(),
                MatchesRegex("GL_INVALID_ENUM after gl.Enable\\(kNotACapability\\) at gl_debug_test.cpp:[0-9]+"));
  }
  EXPECT_NO_THROW(checkGlError(gl(), "nothing"));  // the error was drained
}

TEST_F(GlDebugTest, MacroChecksVoidCallsAndPassesResultsThrough) {
  const auto& gl = this->gl();
  EXPECT_THROW(SDFWB_GL_CHECK(gl, gl.Enable(kNotACapability)), GlError);
  GLuint shader = SDFWB_GL_CHECK(gl, gl.CreateShader(GL_FRAGMENT_SHADER));
  EXPECT_NE(shader, 0u);
  SDFWB_GL_CHECK(gl, gl.DeleteShader(shader));
  try {
    SDFWB_GL_CHECK(gl, gl.BindTexture(GL_TEXTURE_2D, 0xFFFFFF));
    FAIL() << "binding a name never generated is an error in core profiles";
  } catch (const GlError& error) {
    EXPECT_THAT(error.what(), HasSubstr("GL_INVALID_OPERATION after gl.BindTexture(GL_TEXTURE_2D, 0xFFFFFF)"));
  }
}

}  // namespace
