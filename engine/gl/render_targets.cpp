#include "gl/render_targets.h"

#include <string>
#include <vector>

namespace sdfwb::gl {

using glcontext::GlError;

RenderTargets makeRenderTargets(const glcontext::GlFunctions& gl, int width, int height) {
    RenderTargets t{glcontext::makeFramebuffer(gl), glcontext::makeTexture(gl), glcontext::makeTexture(gl), width,
                    height};
    for (GLuint texture : {t.color.get(), t.stats.get()}) {
        gl.BindTexture(GL_TEXTURE_2D, texture);
        gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width, height, 0, GL_RGBA, GL_FLOAT, nullptr);
        gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    }
    gl.BindTexture(GL_TEXTURE_2D, 0);
    gl.BindFramebuffer(GL_FRAMEBUFFER, t.framebuffer.get());
    gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, t.color.get(), 0);
    gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, t.stats.get(), 0);
    const GLenum buffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    gl.DrawBuffers(2, buffers);
    if (gl.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        throw GlError("GL backend: float render targets of " + std::to_string(width) + "x" + std::to_string(height) +
                      " are not supported by this context");
    }
    return t;
}

namespace {
std::vector<float> readAttachment(const glcontext::GlFunctions& gl, GLenum attachment, int x, int y, int w, int h) {
    std::vector<float> pixels(static_cast<size_t>(w) * static_cast<size_t>(h) * 4);
    gl.ReadBuffer(attachment);
    gl.PixelStorei(GL_PACK_ALIGNMENT, 4);
    gl.ReadPixels(x, y, w, h, GL_RGBA, GL_FLOAT, pixels.data());
    return pixels;
}
}  // namespace

void readFrameRegion(const glcontext::GlFunctions& gl, const RenderTargets& targets, int x, int y, int w, int h,
                     int samples, image::Frame& frame) {
    // GL rows start at the bottom; frames start at the top
    const int glY = targets.height - (y + h);
    std::vector<float> color = readAttachment(gl, GL_COLOR_ATTACHMENT0, x, glY, w, h);
    std::vector<float> stats = readAttachment(gl, GL_COLOR_ATTACHMENT1, x, glY, w, h);
    const float n = static_cast<float>(samples);
    for (int row = 0; row < h; ++row) {
        size_t source = static_cast<size_t>(h - 1 - row) * static_cast<size_t>(w);
        size_t target = static_cast<size_t>(y + row) * static_cast<size_t>(targets.width) + static_cast<size_t>(x);
        for (int col = 0; col < w; ++col) {
            size_t s = (source + static_cast<size_t>(col)) * 4, t = target + static_cast<size_t>(col);
            for (size_t c = 0; c < 3; ++c) frame.color.rgb[3 * t + c] = color[s + c] / n;
            frame.steps[t] = stats[s] / n;
            frame.evaluations[t] = stats[s + 3] / n;
            frame.coverage[t] = stats[s + 1] / n;
            frame.depth[t] = stats[s + 1] > 0.0f ? stats[s + 2] / stats[s + 1] : 0.0f;
        }
    }
}

}  // namespace sdfwb::gl
