#pragma once
// Parsing "WIDTHxHEIGHT" command-line values.

#include <string>
#include <utility>

namespace sdfwb::app {

// "WxH" -> (W, H), each from 1 to scene::kMaxImageSize; throws std::runtime_error quoting the text.
std::pair<int, int> parseSizeArgument(const std::string& text);

}  // namespace sdfwb::app
