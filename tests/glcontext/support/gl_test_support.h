#pragma once
// The rule for every test that needs OpenGL: when no context can be made the
// test is skipped, unless SDFWB_REQUIRE_GL=1 (CI sets it), where a missing GL
// path is a failure. Link sdfwb_gl_test_support and either derive a fixture
// from GlTest or call makeHeadlessContext() and SDFWB_SKIP_OR_FAIL_WITHOUT_GL.

#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "glcontext/osmesa_context.h"

namespace sdfwb::test {

// True when the environment sets SDFWB_REQUIRE_GL=1.
bool glRequired();

// Sets MESA_SHADER_CACHE_DISABLE=true, so shaders compile cold as in CI
// (and compile times mean something). Mesa reads it when the process makes
// its first context; makeHeadlessContext() calls it first.
void disableMesaShaderCache();

// A headless (OSMesa) context, current on the calling thread, with Mesa's
// shader cache disabled; or null, with the reason in `whyNot`.
std::unique_ptr<glcontext::OsMesaContext> makeHeadlessContext(std::string& whyNot);

// A fixture holding a current headless context for each test. SetUp skips
// the test, or fails it when GL is required, if no context can be made.
class GlTest : public ::testing::Test {
 protected:
  void SetUp() override;
  void TearDown() override;

  glcontext::OsMesaContext& context() { return *context_; }
  const glcontext::GlFunctions& gl() { return context_->gl(); }

 private:
  std::unique_ptr<glcontext::OsMesaContext> context_;
};

}  // namespace sdfwb::test

// Ends the current test (or SetUp) because no GL context is available:
// skipped normally, failed when SDFWB_REQUIRE_GL=1. `reason` is streamed.
#define SDFWB_SKIP_OR_FAIL_WITHOUT_GL(reason)                                       \
  do {                                                                              \
    if (::sdfwb::test::glRequired()) {                                              \
      GTEST_FAIL() << "no OpenGL context, and SDFWB_REQUIRE_GL=1: " << (reason);    \
    } else {                                                                        \
      GTEST_SKIP() << "no OpenGL context (set SDFWB_REQUIRE_GL=1 to fail instead): " \
                   << (reason);                                                     \
    }                                                                               \
  } while (false)
