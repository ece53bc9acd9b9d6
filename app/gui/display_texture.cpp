#include "app/gui/display_texture.h"

#include <algorithm>
#include <cstdint>

#include "image/encoding.h"

namespace sdfwb::app::gui {

DisplayTexture::DisplayTexture(const glcontext::GlFunctions& gl) : gl_(gl), texture_(glcontext::makeTexture(gl)) {
    gl_.BindTexture(GL_TEXTURE_2D, texture_.get());
    gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    gl_.BindTexture(GL_TEXTURE_2D, 0);
}

void DisplayTexture::resize(int width, int height) {
    if (width == width_ && height == height_) return;
    std::vector<std::uint8_t> start = stretched(width, height);
    width_ = width;
    height_ = height;
    gl_.BindTexture(GL_TEXTURE_2D, texture_.get());
    gl_.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
    gl_.TexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, width, height, 0, GL_RGB, GL_UNSIGNED_BYTE, start.data());
    gl_.BindTexture(GL_TEXTURE_2D, 0);
}

std::vector<std::uint8_t> DisplayTexture::stretched(int width, int height) const {
    std::vector<std::uint8_t> out(static_cast<size_t>(width) * static_cast<size_t>(height) * 3, 0);
    if (width_ == 0 || height_ == 0) return out;  // nothing yet: black
    std::vector<std::uint8_t> old(static_cast<size_t>(width_) * static_cast<size_t>(height_) * 3);
    gl_.BindTexture(GL_TEXTURE_2D, texture_.get());
    gl_.PixelStorei(GL_PACK_ALIGNMENT, 1);
    gl_.GetTexImage(GL_TEXTURE_2D, 0, GL_RGB, GL_UNSIGNED_BYTE, old.data());
    gl_.BindTexture(GL_TEXTURE_2D, 0);
    for (int y = 0; y < height; ++y) {
        size_t from = static_cast<size_t>(y * height_ / height) * static_cast<size_t>(width_);
        for (int x = 0; x < width; ++x) {
            size_t s = (from + static_cast<size_t>(x * width_ / width)) * 3;
            std::copy_n(old.begin() + static_cast<long>(s), 3,
                        out.begin() + static_cast<long>((static_cast<size_t>(y) * static_cast<size_t>(width) + x) * 3));
        }
    }
    return out;
}

image::Frame cropFrame(const image::Frame& frame, const render::TileRect& rect) {
    image::Frame out;
    out.color = image::Image(rect.w, rect.h);
    out.steps.resize(out.color.pixelCount());
    out.evaluations.resize(out.color.pixelCount());
    out.coverage.resize(out.color.pixelCount());
    for (int y = 0; y < rect.h; ++y) {
        size_t from = static_cast<size_t>(rect.y + y) * static_cast<size_t>(frame.color.width) + static_cast<size_t>(rect.x);
        size_t to = static_cast<size_t>(y) * static_cast<size_t>(rect.w);
        std::copy_n(frame.color.rgb.begin() + static_cast<long>(3 * from), 3 * rect.w, out.color.rgb.begin() + static_cast<long>(3 * to));
        std::copy_n(frame.steps.begin() + static_cast<long>(from), rect.w, out.steps.begin() + static_cast<long>(to));
        std::copy_n(frame.evaluations.begin() + static_cast<long>(from), rect.w,
                    out.evaluations.begin() + static_cast<long>(to));
        std::copy_n(frame.coverage.begin() + static_cast<long>(from), rect.w, out.coverage.begin() + static_cast<long>(to));
    }
    return out;
}

void DisplayTexture::upload(const image::Frame& frame, const render::TileRect& rect, int scale, bool heat,
                            double maxSteps) {
    image::Frame tile = cropFrame(frame, rect);
    std::vector<std::uint8_t> bytes = image::encodeSrgb8(heat ? image::stepHeatImage(tile, maxSteps) : tile.color);
    // repeat pixels for a reduced-resolution preview, clipped to the texture
    int x0 = rect.x * scale, y0 = rect.y * scale;
    int w = std::min(rect.w * scale, width_ - x0), h = std::min(rect.h * scale, height_ - y0);
    if (w <= 0 || h <= 0) return;
    std::vector<std::uint8_t> scaled(static_cast<size_t>(w) * static_cast<size_t>(h) * 3);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            size_t s = (static_cast<size_t>(y / scale) * static_cast<size_t>(rect.w) + static_cast<size_t>(x / scale)) * 3;
            size_t t = (static_cast<size_t>(y) * static_cast<size_t>(w) + static_cast<size_t>(x)) * 3;
            std::copy_n(bytes.begin() + static_cast<long>(s), 3, scaled.begin() + static_cast<long>(t));
        }
    }
    gl_.BindTexture(GL_TEXTURE_2D, texture_.get());
    gl_.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
    gl_.TexSubImage2D(GL_TEXTURE_2D, 0, x0, y0, w, h, GL_RGB, GL_UNSIGNED_BYTE, scaled.data());
    gl_.BindTexture(GL_TEXTURE_2D, 0);
}

void DisplayTexture::upload(const image::Image& image) {
    resize(image.width, image.height);
    std::vector<std::uint8_t> bytes = image::encodeSrgb8(image);
    gl_.BindTexture(GL_TEXTURE_2D, texture_.get());
    gl_.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
    gl_.TexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, image.width, image.height, GL_RGB, GL_UNSIGNED_BYTE, bytes.data());
    gl_.BindTexture(GL_TEXTURE_2D, 0);
}

}  // namespace sdfwb::app::gui
