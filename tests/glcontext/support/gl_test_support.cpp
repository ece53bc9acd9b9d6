#include "gl_test_support.h"

#include <cstdlib>
#include <string_view>

#include "glcontext/gl_error.h"

namespace sdfwb::test {

bool glRequired() {
  const char* value = std::getenv("SDFWB_REQUIRE_GL");
  return value != nullptr && std::string_view(value) == "1";
}

void disableMesaShaderCache() { setenv("MESA_SHADER_CACHE_DISABLE", "true", 1); }

std::unique_ptr<glcontext::OsMesaContext> makeHeadlessContext(std::string& whyNot) {
  disableMesaShaderCache();
  try {
    return glcontext::OsMesaContext::create();
  } catch (const glcontext::GlError& error) {
    whyNot = error.what();
    return nullptr;
  }
}

void GlTest::SetUp() {
  std::string whyNot;
  context_ = makeHeadlessContext(whyNot);
  if (!context_) SDFWB_SKIP_OR_FAIL_WITHOUT_GL(whyNot);
}

void GlTest::TearDown() { context_.reset(); }

}  // namespace sdfwb::test
