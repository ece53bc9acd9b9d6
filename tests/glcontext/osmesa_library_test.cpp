// OSMesa load failures: each must end in one line naming the cause. No GL
// context is needed, so these run everywhere.
#include "glcontext/osmesa_context.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "glcontext/gl_error.h"

using sdfwb::glcontext::GlError;
using sdfwb::glcontext::OsMesaContext;
using sdfwb::glcontext::OsMesaOptions;
using ::testing::HasSubstr;
using ::testing::Not;

namespace {

std::string creationError(const OsMesaOptions& options) {
  try {
    OsMesaContext::create(options);
  } catch (const GlError& error) {
    return error.what();
  }
  return "(no error)";
}

TEST(OsMesaLibrary, MissingLibraryNamesEveryAttemptWithDlerrorText) {
  OsMesaOptions options;
  options.libraryNames = {"libsdfwb-no-such-osmesa.so.8", "libsdfwb-no-such-osmesa.so"};
  std::string message = creationError(options);
  EXPECT_THAT(message, HasSubstr("cannot load OSMesa"));
  EXPECT_THAT(message, HasSubstr("libsdfwb-no-such-osmesa.so.8: cannot open shared object file"));
  EXPECT_THAT(message, HasSubstr("libsdfwb-no-such-osmesa.so: cannot open shared object file"));
  EXPECT_THAT(message, HasSubstr("libosmesa6"));
  EXPECT_THAT(message, Not(HasSubstr("\n")));
}

TEST(OsMesaLibrary, LibraryWithoutOsMesaSymbolsNamesTheSymbol) {
  OsMesaOptions options;
  options.libraryNames = {"libm.so.6"};  // loads fine, exports no OSMesa API
  std::string message = creationError(options);
  EXPECT_THAT(message, HasSubstr("OSMesa library libm.so.6 has no symbol OSMesaCreateContextAttribs"));
  EXPECT_THAT(message, Not(HasSubstr("\n")));
}

TEST(OsMesaLibrary, EmptyNameListIsReported) {
  OsMesaOptions options;
  options.libraryNames = {};
  EXPECT_THAT(creationError(options), HasSubstr("no library names given"));
}

}  // namespace
