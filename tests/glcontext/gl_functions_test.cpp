#include "glcontext/gl_functions.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <set>
#include <string>

using sdfwb::glcontext::GlError;
using sdfwb::glcontext::GlFunctions;
using sdfwb::glcontext::GlProc;
using ::testing::HasSubstr;
using ::testing::Not;

namespace {

void dummyEntryPoint() {}

#define SDFWB_COUNT_ENTRY(type, name) +1
constexpr int kEntryPointCount = 0 SDFWB_GL_FUNCTIONS(SDFWB_COUNT_ENTRY);
#undef SDFWB_COUNT_ENTRY

TEST(GlFunctions, AsksTheLoaderForEveryEntryPointByItsGlName) {
  std::set<std::string> asked;
  GlFunctions gl = GlFunctions::load([&](const char* name) -> GlProc {
    asked.insert(name);
    return &dummyEntryPoint;
  });
  EXPECT_EQ(static_cast<int>(asked.size()), kEntryPointCount);
  EXPECT_TRUE(asked.count("glCompileShader"));
  EXPECT_TRUE(asked.count("glTexBuffer"));
  EXPECT_TRUE(asked.count("glGetQueryObjectui64v"));
  EXPECT_EQ(reinterpret_cast<GlProc>(gl.CompileShader), &dummyEntryPoint);
  EXPECT_EQ(reinterpret_cast<GlProc>(gl.DeleteSync), &dummyEntryPoint);
}

TEST(GlFunctions, NamesTheFirstMissingEntryPoint) {
  auto loader = [](const char* name) -> GlProc {
    std::string_view wanted(name);
    return wanted == "glFenceSync" || wanted == "glQueryCounter" ? nullptr : &dummyEntryPoint;
  };
  try {
    GlFunctions::load(loader);
    FAIL() << "load() accepted a loader lacking glFenceSync";
  } catch (const GlError& error) {
    EXPECT_THAT(error.what(), HasSubstr("glFenceSync is missing"));
    EXPECT_THAT(error.what(), Not(HasSubstr("glQueryCounter")));
  }
}

}  // namespace
