#pragma once
// A GLSL-backend render spread over many short calls, for an interactive
// caller (the GUI viewport) that must never block: each call issues draws
// (one tile x one AA sub-sample each) until its time budget is spent, and
// reads back the tiles whose sub-samples are all done.
//
// Runs in the context current on the calling thread, with a renderer made
// for that context; the program's shader should already be built there
// (GlRenderer::adoptProgram), or the first advance() builds it.

#include <vector>

#include "gl/gl_renderer.h"
#include "gl/render_targets.h"

namespace sdfwb::gl {

// A rectangle of the frame, rows counted from the top.
struct TileRect {
    int x = 0, y = 0, w = 0, h = 0;
};

class ProgressiveRender {
public:
    // Makes the float targets for program.width x program.height.
    ProgressiveRender(GlRenderer& renderer, program::Program program, int tileSize = 64);

    // Issues draws, waiting for each with a fence (and timing it with a GL
    // timer query), until `budgetSeconds` have
    // passed or the render is complete; returns the tiles completed in this
    // call (already read into frame()). At least one draw runs per call.
    std::vector<TileRect> advance(double budgetSeconds);

    bool done() const { return next_ >= tiles_.size(); }
    // Fraction of draws done, 0 to 1.
    double progress() const;
    // The frame so far: finished tiles hold their pixels, the rest zeros.
    const image::Frame& frame() const { return frame_; }
    const program::Program& program() const { return program_; }
    // Wall-clock seconds spent in advance() so far.
    double drawSeconds() const { return drawSeconds_; }
    // GPU seconds of the draws so far (GL timer queries).
    double gpuSeconds() const { return gpuSeconds_; }

private:
    GlRenderer& renderer_;
    const glcontext::GlFunctions& gl_;
    program::Program program_;
    RenderTargets targets_;
    std::vector<TileRect> tiles_;
    size_t next_ = 0;       // tile being drawn
    int subsample_ = 0;     // next sub-sample of that tile, 0 .. aa*aa-1
    image::Frame frame_;
    glcontext::GlObject timer_;  // GL_TIME_ELAPSED query around each draw
    double drawSeconds_ = 0;
    double gpuSeconds_ = 0;
};

}  // namespace sdfwb::gl
