#include "app/gui/window_capture.h"

#include <cstdint>
#include <vector>

#include "image/encoding.h"
#include "image/image_io.h"

namespace sdfwb::app::gui {

void captureWindow(const glcontext::GlFunctions& gl, int width, int height, const std::filesystem::path& path) {
    std::vector<std::uint8_t> pixels(static_cast<size_t>(width) * static_cast<size_t>(height) * 4);
    gl.ReadBuffer(GL_BACK);
    gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
    gl.ReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
    // The window holds display-encoded bytes; the image writer takes linear
    // values and encodes them again with the same function, which gives the
    // bytes back exactly (decodeSrgb8 is its inverse on the 256 levels).
    image::Image shot(width, height);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            size_t source = (static_cast<size_t>(height - 1 - y) * static_cast<size_t>(width) + static_cast<size_t>(x)) * 4;
            size_t target = (static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)) * 3;
            for (size_t c = 0; c < 3; ++c) shot.rgb[target + c] = image::decodeSrgb8(pixels[source + c]);
        }
    }
    image::writeImage(path, shot, {{"sdfwb:source", "sdf-workbench gui window"}});
}

}  // namespace sdfwb::app::gui
