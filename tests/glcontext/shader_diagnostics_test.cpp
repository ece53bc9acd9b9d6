#include "glcontext/shader_diagnostics.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

using sdfwb::glcontext::formatDiagnostics;
using sdfwb::glcontext::parseInfoLog;
using sdfwb::glcontext::ShaderDiagnostic;

namespace {

TEST(ParseInfoLog, ReadsMesaLines) {
  // Verbatim from llvmpipe (Mesa 22.3).
  const char* log =
      "0:4(11): error: `foo' undeclared\n"
      "0:4(6): error: cannot construct `vec4' from a non-numeric data type\n"
      "0:6(8): error: no function with name 'bar'\n";
  std::vector<ShaderDiagnostic> diagnostics = parseInfoLog(log, GL_FRAGMENT_SHADER);
  ASSERT_EQ(diagnostics.size(), 3u);
  EXPECT_EQ(diagnostics[0].stage, static_cast<GLenum>(GL_FRAGMENT_SHADER));
  EXPECT_EQ(diagnostics[0].line, 4);
  EXPECT_EQ(diagnostics[0].column, 11);
  EXPECT_EQ(diagnostics[0].message, "error: `foo' undeclared");
  EXPECT_EQ(diagnostics[2].line, 6);
  EXPECT_EQ(diagnostics[2].column, 8);
}

TEST(ParseInfoLog, ReadsNvidiaAndErrorPrefixedLines) {
  std::vector<ShaderDiagnostic> diagnostics = parseInfoLog(
      "0(12) : error C1008: undefined variable \"foo\"\n"
      "ERROR: 0:7: 'bar' : undeclared identifier\n"
      "WARNING: 0:3: extension not supported\n",
      GL_VERTEX_SHADER);
  ASSERT_EQ(diagnostics.size(), 3u);
  EXPECT_EQ(diagnostics[0].line, 12);
  EXPECT_EQ(diagnostics[0].column, 0);
  EXPECT_EQ(diagnostics[0].message, "error C1008: undefined variable \"foo\"");
  EXPECT_EQ(diagnostics[1].line, 7);
  EXPECT_EQ(diagnostics[1].message, "error: 'bar' : undeclared identifier");
  EXPECT_EQ(diagnostics[2].line, 3);
  EXPECT_EQ(diagnostics[2].message, "warning: extension not supported");
}

TEST(ParseInfoLog, KeepsUnlocatedLinesWholeAndDropsBlankOnes) {
  std::vector<ShaderDiagnostic> diagnostics =
      parseInfoLog("error: unresolved reference to function `helper'\n\n  \n", 0);
  ASSERT_EQ(diagnostics.size(), 1u);
  EXPECT_EQ(diagnostics[0].line, 0);
  EXPECT_EQ(diagnostics[0].message, "error: unresolved reference to function `helper'");
}

TEST(FormatDiagnostics, EchoesTheSourceLineWithACaret) {
  const char* source = "#version 330 core\nvoid main() {\n  x = 1.0;\n}\n";
  std::string text =
      formatDiagnostics("fragment shader", source, {{GL_FRAGMENT_SHADER, 3, 2, "error: `x' undeclared"}});
  EXPECT_EQ(text,
            "fragment shader:3:2: error: `x' undeclared\n"
            "    3 |   x = 1.0;\n"
            "      |   ^\n");
}

TEST(FormatDiagnostics, MapsMesaColumnsThroughCollapsedWhitespaceAndComments) {
  // Mesa counts columns after its preprocessor has turned every run of
  // whitespace and comments into one space: `foo` is column 11 in both.
  const char* source = "\n\n\n      o =      vec4(foo);\n\t\to = /* c */ vec4(foo);\n";
  std::string text = formatDiagnostics("fs", source,
                                       {{GL_FRAGMENT_SHADER, 4, 11, "error: `foo' undeclared"},
                                        {GL_FRAGMENT_SHADER, 5, 11, "error: `foo' undeclared"}});
  EXPECT_EQ(text,
            "fs:4:11: error: `foo' undeclared\n"
            "    4 |       o =      vec4(foo);\n"
            "      |                     ^\n"
            "fs:5:11: error: `foo' undeclared\n"
            "    5 | \t\to = /* c */ vec4(foo);\n"
            "      | \t\t                 ^\n");
}

TEST(FormatDiagnostics, ConsecutiveMessagesOnOneLineShareOneEcho) {
  const char* source = "a\nb = f(x);\n";
  std::string text = formatDiagnostics("fs", source,
                                       {{GL_FRAGMENT_SHADER, 2, 7, "error: `x' undeclared"},
                                        {GL_FRAGMENT_SHADER, 2, 5, "error: no matching function"},
                                        {GL_FRAGMENT_SHADER, 1, 1, "error: a"}});
  EXPECT_EQ(text,
            "fs:2:7: error: `x' undeclared\n"
            "    2 | b = f(x);\n"
            "      |       ^\n"
            "fs:2:5: error: no matching function\n"
            "fs:1:1: error: a\n"
            "    1 | a\n"
            "      | ^\n");
}

TEST(FormatDiagnostics, MessagesWithoutALineHaveNoEcho) {
  EXPECT_EQ(formatDiagnostics("program link", "", {{0, 0, 0, "error: link failed"}}),
            "program link: error: link failed\n");
  // A line past the end of the source has nothing to echo.
  EXPECT_EQ(formatDiagnostics("fs", "one line", {{0, 9, 0, "error: x"}}), "fs:9: error: x\n");
}

}  // namespace
