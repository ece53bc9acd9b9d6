#pragma once
// An 8-bit RGB texture the UI draws with ImGui::Image. Everything reaches it
// through image::encodeSrgb8, the encoding image files use, so the viewport
// shows what a snapshot writes.

#include <cstdint>
#include <vector>

#include "glcontext/gl_functions.h"
#include "glcontext/gl_object.h"
#include "image/image.h"
#include "render/tiles.h"

namespace sdfwb::app::gui {

class DisplayTexture {
public:
    explicit DisplayTexture(const glcontext::GlFunctions& gl);

    // Reallocates when the size differs, starting from the old image
    // stretched to the new size (not black while the new one renders).
    void resize(int width, int height);
    // Uploads `rect` of `frame`, each pixel repeated `scale` x `scale` times
    // (a reduced-resolution preview fills the full-size texture). With
    // `heat`, the step-count heat image instead of the colour.
    void upload(const image::Frame& frame, const render::TileRect& rect, int scale, bool heat, double maxSteps);
    // Uploads a whole image of the texture's size.
    void upload(const image::Image& image);

    void* id() const { return reinterpret_cast<void*>(static_cast<std::uintptr_t>(texture_.get())); }
    int width() const { return width_; }
    int height() const { return height_; }

private:
    // The current contents resized (nearest pixel) to width x height; black
    // before the first allocation.
    std::vector<std::uint8_t> stretched(int width, int height) const;

    const glcontext::GlFunctions& gl_;
    glcontext::GlObject texture_;
    int width_ = 0, height_ = 0;
};

// The part `rect` of `frame` as a frame of its own.
image::Frame cropFrame(const image::Frame& frame, const render::TileRect& rect);

}  // namespace sdfwb::app::gui
