// quoted() and escapedExcerpt(): user text in a one-line message stays one short line.

#include <string>

#include <gtest/gtest.h>

#include "io/quoted_text.h"

namespace sdfwb::io {
namespace {

TEST(QuotedText, PlainTextIsQuotedAsIs) {
    EXPECT_EQ(io::quoted("radius"), "\"radius\"");
    EXPECT_EQ(io::quoted(""), "\"\"");
    EXPECT_EQ(escapedExcerpt("a/b.json"), "a/b.json");
}

TEST(QuotedText, QuotesBackslashesAndControlBytesAreEscaped) {
    EXPECT_EQ(io::quoted(std::string("a\"b\\c\nd\te\x01") + '\0' + "\x7f\xff"),
              "\"a\\\"b\\\\c\\nd\\te\\x01\\x00\\x7f\\xff\"");
}

TEST(QuotedText, LongTextIsCutWithItsLength) {
    std::string longText(kMaxQuotedCharacters + 20, 'a');
    EXPECT_EQ(escapedExcerpt(longText),
              std::string(kMaxQuotedCharacters, 'a') + "... (" + std::to_string(longText.size()) + " bytes)");
    EXPECT_EQ(escapedExcerpt(std::string(kMaxQuotedCharacters, 'b')), std::string(kMaxQuotedCharacters, 'b'));
}

TEST(QuotedText, EscapesDoNotCountAgainstTheCut) {
    // the cut counts characters of the text, not of the escapes
    std::string newlines(kMaxQuotedCharacters + 1, '\n');
    std::string expected;
    for (size_t i = 0; i < kMaxQuotedCharacters; ++i) expected += "\\n";
    EXPECT_EQ(escapedExcerpt(newlines), expected + "... (" + std::to_string(newlines.size()) + " bytes)");
}

}  // namespace
}  // namespace sdfwb::io
