#include "app/size_argument.h"

#include <sstream>
#include <stdexcept>

#include "scene/scene.h"

namespace sdfwb::app {

std::pair<int, int> parseSizeArgument(const std::string& text) {
    int w = 0, h = 0;
    char x = 0, extra = 0;
    std::istringstream in(text);
    if (!(in >> w >> x >> h) || (x != 'x' && x != 'X') || (in >> extra) || w < 1 || h < 1 || w > scene::kMaxImageSize ||
        h > scene::kMaxImageSize) {
        throw std::runtime_error("--size: expected WIDTHxHEIGHT with each from 1 to " +
                                 std::to_string(scene::kMaxImageSize) + " (got \"" + text + "\")");
    }
    return {w, h};
}

}  // namespace sdfwb::app
