#include "app/size_argument.h"

#include <sstream>
#include <stdexcept>

namespace sdfwb::app {

std::pair<int, int> parseSizeArgument(const std::string& text) {
    int w = 0, h = 0;
    char x = 0, extra = 0;
    std::istringstream in(text);
    if (!(in >> w >> x >> h) || (x != 'x' && x != 'X') || (in >> extra) || w < 1 || h < 1 || w > 16384 || h > 16384) {
        throw std::runtime_error("--size: expected WIDTHxHEIGHT with each from 1 to 16384 (got \"" + text + "\")");
    }
    return {w, h};
}

}  // namespace sdfwb::app
