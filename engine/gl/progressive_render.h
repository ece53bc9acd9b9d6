#pragma once
// The GLSL backend's render loop: draws of one tile x one AA sub-sample each,
// over render::tilesToRender, into float targets, reading back each tile once all
// its sub-samples are done. GlRenderer::render runs it to the end; the GUI
// viewport spreads it over frames within a time budget (advance()).
//
// Runs in the context current on the calling thread, with a renderer made
// for that context; the program's shader should already be built there
// (GlRenderer::adoptProgram), or the first draw builds it.

#include <functional>
#include <vector>

#include "gl/gl_renderer.h"
#include "gl/render_targets.h"
#include "render/render_backend.h"

namespace sdfwb::gl {

// The smallest tile side a progressive render draws: on the 1001-sphere
// molecule 8 x 8 costs about 4 ms a draw (16 x 16 cost 17 ms, and the
// window's frames as much); smaller, a draw's fixed cost would dominate.
inline constexpr int kMinTileSize = 8;

class GlProgressiveRender : public render::ProgressiveRender {
public:
    // Makes the float targets for program.width x program.height and draws the
    // tiles of control.region (all of them without one), control.tileSize
    // pixels per side (defaultTileSize when 0, never under kMinTileSize).
    GlProgressiveRender(GlRenderer& renderer, program::Program program, const render::RenderControl& control,
                        int defaultTileSize = 64);

    // Issues draws, waiting for each with a fence (and timing it with a GL
    // timer query), while another draw as long as the last one still ends
    // within `budgetSeconds`, until the render is complete. At least one draw
    // runs per call.
    std::vector<render::TileRect> advance(double budgetSeconds) override;
    // Issues draws while `another()` (asked before each) says so, calling
    // `afterEach(drawsDone, drawsTotal)` after each; returns the tiles completed.
    std::vector<render::TileRect> draw(const std::function<bool()>& another,
                                       const std::function<void(int, int)>& afterEach = {});

    bool done() const override { return next_ >= tiles_.size(); }
    double progress() const override;
    const image::Frame& frame() const override { return frame_; }
    const program::Program& program() const override { return program_; }
    double seconds() const override { return drawSeconds_; }
    // GPU seconds of the draws so far (GL timer queries).
    double deviceSeconds() const override { return gpuSeconds_; }

private:
    int drawsDone() const;
    int drawsTotal() const;

    GlRenderer& renderer_;
    const glcontext::GlFunctions& gl_;
    program::Program program_;
    RenderTargets targets_;
    std::vector<render::TileRect> tiles_;
    size_t next_ = 0;    // tile being drawn
    int subsample_ = 0;  // next sub-sample of that tile, 0 .. aa*aa-1
    image::Frame frame_;
    glcontext::GlObject timer_;  // GL_TIME_ELAPSED query around each draw
    double drawSeconds_ = 0;
    double gpuSeconds_ = 0;
};

}  // namespace sdfwb::gl
