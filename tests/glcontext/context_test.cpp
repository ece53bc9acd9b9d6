#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <iostream>

#include "gl_test_support.h"
#include "glcontext/gl_error.h"

using sdfwb::glcontext::GlError;
using sdfwb::glcontext::OsMesaContext;
using sdfwb::glcontext::OsMesaOptions;
using ::testing::HasSubstr;

namespace {

using OsMesaContextTest = sdfwb::test::GlTest;

TEST_F(OsMesaContextTest, IsACoreProfileContextOnLlvmpipe) {
  const auto& info = context().info();
  std::cout << "GL_RENDERER: " << info.renderer << "\nGL_VERSION: " << info.version
            << "\nGL_SHADING_LANGUAGE_VERSION: " << info.glslVersion << "\nOSMesa library: "
            << context().libraryName() << "\n";
  RecordProperty("renderer", info.renderer);
  EXPECT_THAT(info.renderer, HasSubstr("llvmpipe"))
      << "the parity facts in TOOLCHAIN.md were measured on llvmpipe";
  EXPECT_TRUE(info.coreProfile);
  EXPECT_GE(info.major * 10 + info.minor, 33);
}

TEST_F(OsMesaContextTest, ReleaseLeavesNoContextCurrentAndMakeCurrentRestoresIt) {
  context().releaseCurrent();
  // With nothing current, Mesa's dispatch answers every call with nothing.
  EXPECT_EQ(gl().GetString(GL_RENDERER), nullptr);
  context().makeCurrent();
  ASSERT_NE(gl().GetString(GL_RENDERER), nullptr);
  EXPECT_EQ(reinterpret_cast<const char*>(gl().GetString(GL_RENDERER)), context().info().renderer);
}

TEST_F(OsMesaContextTest, ReleasingAContextThatIsNotCurrentChangesNothing) {
  auto other = context().createShared();
  other->releaseCurrent();
  EXPECT_NE(gl().GetString(GL_RENDERER), nullptr);
}

TEST_F(OsMesaContextTest, UnavailableVersionFailsWithOneLine) {
  OsMesaOptions options;
  options.major = 9;
  options.minor = 9;
  try {
    OsMesaContext::create(options);
    FAIL() << "OSMesa claimed an OpenGL 9.9 context";
  } catch (const GlError& error) {
    EXPECT_THAT(error.what(), HasSubstr("could not create an OpenGL 9.9 core profile context"));
    EXPECT_THAT(error.what(), ::testing::Not(HasSubstr("\n")));
  }
}

TEST_F(OsMesaContextTest, OsMesaHandsOutStubsForUnknownGlNames) {
  // Why GlFunctions::load cannot detect missing functions through OSMesa and
  // create() checks the version instead.
  EXPECT_NE(context().getProcAddress("glSdfwbNoSuchFunction"), nullptr);
  EXPECT_EQ(context().getProcAddress("SdfwbNoSuchFunction"), nullptr);
}

TEST_F(OsMesaContextTest, FenceAndTimerQueryWork) {
  const auto& gl = this->gl();
  GLuint queries[2] = {0, 0};
  gl.GenQueries(2, queries);
  gl.QueryCounter(queries[0], GL_TIMESTAMP);
  gl.Clear(GL_COLOR_BUFFER_BIT);
  gl.QueryCounter(queries[1], GL_TIMESTAMP);
  GLsync fence = gl.FenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
  ASSERT_NE(fence, nullptr);
  GLenum waited = gl.ClientWaitSync(fence, GL_SYNC_FLUSH_COMMANDS_BIT, 5'000'000'000ull);
  EXPECT_TRUE(waited == GL_ALREADY_SIGNALED || waited == GL_CONDITION_SATISFIED) << waited;
  gl.DeleteSync(fence);
  GLuint64 begin = 0, end = 0;
  gl.GetQueryObjectui64v(queries[0], GL_QUERY_RESULT, &begin);
  gl.GetQueryObjectui64v(queries[1], GL_QUERY_RESULT, &end);
  EXPECT_GT(begin, 0u);
  EXPECT_GE(end, begin);
  gl.DeleteQueries(2, queries);
  EXPECT_EQ(gl.GetError(), static_cast<GLenum>(GL_NO_ERROR));
}

}  // namespace
