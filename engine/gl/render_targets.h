#pragma once
// The GLSL backend's float render targets: one framebuffer with two RGBA32F
// textures, the colour sum and the statistics sum (steps, coverage) of the
// sub-sample passes, and their read-back into a Frame.

#include "glcontext/gl_functions.h"
#include "glcontext/gl_object.h"
#include "image/image.h"

namespace sdfwb::gl {

struct RenderTargets {
    glcontext::GlObject framebuffer, color, stats;
    int width = 0;
    int height = 0;
};

// Creates, attaches and leaves bound (GL_FRAMEBUFFER) targets of the given
// size. Throws glcontext::GlError when the context cannot render to them.
RenderTargets makeRenderTargets(const glcontext::GlFunctions& gl, int width, int height);

// Reads the rectangle [x, x+w) x [y, y+h) (frame coordinates: rows from the
// top) of the bound targets into `frame`, dividing the sums by `samples`.
// `frame` must already have the targets' size.
void readFrameRegion(const glcontext::GlFunctions& gl, const RenderTargets& targets, int x, int y, int w, int h,
                     int samples, image::Frame& frame);

}  // namespace sdfwb::gl
