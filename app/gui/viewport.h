#pragma once
// The live viewport's rendering: what to render for the current scene and
// view, in stages (a reduced-resolution AA 1 preview while the user
// interacts; AA 1 then the scene's AA when idle), by the GLSL backend in the
// window's context (progressive tiles within a per-frame budget, programs
// built by a worker; the CPU backend stands in while a program is built) or
// by the CPU backend on a worker thread, and both for the compare view. The UI thread calls update() once per frame; nothing in
// it waits on a render or a compile.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "app/gui/cpu_jobs.h"
#include "app/gui/display_texture.h"
#include "gl/program_builder.h"
#include "gl/progressive_render.h"
#include "image/compare.h"
#include "scene/scene.h"
#include "ui/ui_state.h"

namespace sdfwb::app::gui {

struct ViewportStats {
    int width = 0, height = 0;           // of the image being shown
    int aa = 1;
    double renderSeconds = 0;            // of the last finished stage
    double compileSeconds = 0;           // of the last adopted program
    double gpuSeconds = 0;               // GL timer queries of the last finished GL stage
    image::FrameStats frame;             // of the last finished stage
    std::string status;                  // "compiling shader", "refining 40%", "done"
    int compiles = 0;                    // programs adopted from the builder
};

class Viewport {
public:
    // `context` is the window's context, current on this (the UI) thread.
    explicit Viewport(glcontext::GlContext& context);
    ~Viewport();

    // Drives rendering for `scene` at `revision`, drawn at width x height
    // pixels; spends at most about `budgetSeconds` on GL draws.
    void update(const scene::Scene& scene, std::uint64_t revision, const ui::UiState& ui, int width, int height,
                bool interacting, double budgetSeconds);

    // Every stage of every backend in use is finished for the last update's request.
    bool idle() const;

    // The textures to show: the chosen backend's image; in compare mode the
    // GL image (main), the CPU image (second) and the difference heat (difference).
    const DisplayTexture& main() const { return glShown_ ? glTexture_ : cpuTexture_; }
    const DisplayTexture& second() const { return cpuTexture_; }
    const DisplayTexture& difference() const { return differenceTexture_; }
    // The compare view's metrics, once both backends finished the same image.
    const std::optional<image::Comparison>& comparison() const { return comparison_; }

    const ViewportStats& stats() const { return stats_; }
    // A shader build failure, or "" (shown in the UI; the CPU backend still works).
    const std::string& error() const { return error_; }
    const glcontext::GlContextInfo& glInfo() const { return context_.info(); }

private:
    struct Stage {
        int scale = 1;  // the render is width/scale x height/scale, shown scaled up
        int aa = 1;
    };
    void plan(const scene::Scene& scene, const ui::UiState& ui, int width, int height, bool interacting);
    void updateGl(double budgetSeconds);
    void updateCpu();
    program::Program programFor(const Stage& stage) const;
    void finishStage(const image::Frame& frame, double seconds, const Stage& stage, bool gl);

    glcontext::GlContext& context_;
    gl::GlRenderer renderer_;
    gl::ProgramBuilder builder_;
    CpuJobQueue cpuJobs_;
    DisplayTexture glTexture_, cpuTexture_, differenceTexture_;

    // The request being served.
    std::uint64_t requestKey_ = 0;
    std::uint64_t planId_ = 0;
    scene::Scene scene_;
    std::vector<Stage> stages_;
    int width_ = 0, height_ = 0;
    bool useGl_ = true, useCpu_ = false, compare_ = false, heat_ = false;
    bool glShown_ = true;
    // While the GL program for a new structure is still being built, the CPU
    // backend renders the request meanwhile, so the viewport never sits on a
    // stale or black image; the GL image replaces it once its first stage is done.
    bool cpuFallback_ = false;
    bool glWaiting_ = false;  // the GL stage waits for the builder

    size_t glStage_ = 0;
    std::unique_ptr<gl::ProgressiveRender> glJob_;
    std::optional<std::uint64_t> failedStructure_;
    size_t cpuStage_ = 0;
    bool cpuSubmitted_ = false;
    std::optional<image::Frame> glFinal_, cpuFinal_;
    std::optional<image::Comparison> comparison_;

    // Measured cost of one GL sample (pixel x AA sub-sample), which sizes
    // the next job's tiles so that one draw stays well inside the budget.
    double secondsPerSample_ = 0;
    int tileSize() const;
    // The preview's reduction factor while the user interacts.
    int previewScale() const;

    ViewportStats stats_;
    std::string error_;
};

}  // namespace sdfwb::app::gui
