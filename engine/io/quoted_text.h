#pragma once
// User text quoted in one-line messages: a key, a name or a formula from a file
// can be megabytes long or hold control bytes, and an error line must stay one
// short line.

#include <cstddef>
#include <string>
#include <string_view>

namespace sdfwb::io {

// How many characters of user text a message quotes before cutting it short.
inline constexpr std::size_t kMaxQuotedCharacters = 80;

// `text` in double quotes, with '"', '\\' and bytes outside printable ASCII
// written as escapes (\n, \t, \xNN), cut after kMaxQuotedCharacters with
// "... (N bytes)" so the reader knows how long it was.
std::string quoted(std::string_view text);

// Like quoted() without the quotes, for text that a message already frames
// (a JSON path, a file name).
std::string escapedExcerpt(std::string_view text);

}  // namespace sdfwb::io
