#pragma once
// The live viewport's rendering: what to render for the current scene and
// view, in stages (a reduced-resolution AA 1 preview, then AA 1 and the
// scene's AA when idle; the preview alone while the user interacts), by the
// backends behind the backend contract: the GL backend in the window's
// context (progressive draws within a per-frame budget, shaders built by a
// worker), the CPU backend on its job queue. Each lane's next program is
// compiled from the scene on the viewport's compile worker
// (ui/program_compiler.h); until it is ready the lane's last image stays,
// marked outdated when it shows an earlier state. The decisions (which
// backends render, which image each slot shows) are app/gui/view_choice.h's.
// The UI thread calls update() once per frame; nothing in it waits on a
// render or a compile.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/gui/display_texture.h"
#include "app/gui/view_choice.h"
#include "glcontext/gl_context.h"
#include "image/compare.h"
#include "jobs/job_queue.h"
#include "program/scene_images.h"
#include "render/render_backend.h"
#include "scene/scene.h"
#include "ui/program_compiler.h"
#include "ui/ui_state.h"

namespace sdfwb::app::gui {

struct ViewportStats {
    int width = 0, height = 0;  // of the image being shown
    int aa = 1;
    double renderSeconds = 0;   // of the last finished stage
    double compileSeconds = 0;  // of the last program built
    double gpuSeconds = 0;      // GL timer queries of the last finished GL stage
    image::FrameStats frame;    // of the last finished stage
    std::string status;         // "compiling shader", "refining 40%", "done"
    int compiles = 0;           // programs built for the viewport
};

// What one view slot draws: a texture and what to say over it ("" or a note
// such as "CPU image until the GLSL one is ready").
struct SlotImage {
    const DisplayTexture* texture = nullptr;
    std::string note;
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

    // The images to show: the chosen backend's; in compare mode the GL
    // image (main), the CPU image (second) and the difference heat.
    SlotImage main() const { return slot(compare_ ? Source::Gl : wanted_); }
    SlotImage second() const { return slot(Source::Cpu); }
    SlotImage difference() const;
    // The compare view's metrics, once both backends finished the same image.
    const std::optional<image::Comparison>& comparison() const { return comparison_; }

    const ViewportStats& stats() const { return stats_; }
    // A shader build failure, or "" (shown in the UI; the CPU backend still works).
    const std::string& error() const { return error_; }
    // The error as the viewport and the status bar show it: named once as the
    // GL backend's (the engine's messages already start "GL backend: ").
    std::string errorLine() const;
    const glcontext::GlContextInfo& glInfo() const { return context_.info(); }

private:
    struct Stage {
        bool preview = false;  // at a reduced resolution (previewScale), shown scaled up
        int aa = 1;
    };
    // What a lane's compile is of.
    struct LaneCompile {
        std::uint64_t state = 0;
        size_t stage = 0;
        int scale = 1;
        bool operator==(const LaneCompile&) const = default;
    };
    // One backend with its texture and its share of the current request.
    struct Lane {
        Lane(Source source, std::unique_ptr<render::Backend> backend, const glcontext::GlFunctions& gl,
             jobs::JobQueue& compiles)
            : source(source),
              backend(std::move(backend)),
              texture(gl),
              // the worker also reads the environment's images, which the GL
              // backend would otherwise read on the UI thread at its first render
              compiler(
                  std::make_unique<ui::ProgramCompiler<LaneCompile>>(compiles, program::compileSceneReadingImages)) {}
        Source source;
        std::unique_ptr<render::Backend> backend;
        DisplayTexture texture;
        ImageContent content;
        std::unique_ptr<render::ProgressiveRender> job;
        size_t stage = 0;                      // next stage to render (or the one rendering)
        std::optional<program::Program> next;  // the program of that stage, once compiled
        int scale = 1;                         // of that program: width/scale x height/scale
        std::uint64_t nextState = 0;           // of that program: state_, or during a drag an earlier one
        // makes `next` on the viewport's compile worker
        std::unique_ptr<ui::ProgramCompiler<LaneCompile>> compiler;
        std::optional<image::Frame> final;  // the last stage's frame of the current state
        // Measured cost of one sample (pixel x AA sub-sample), which sizes
        // previews and, on GL, tiles so that one draw stays inside the budget:
        // the last stage's, and the last whole-program render's
        // (previewSecondsPerSample).
        double secondsPerSample = 0;
        double secondsPerWholeSample = 0;
        bool rendersWhole = false;  // the running job is a preview started while the grid was pending
    };

    void plan(const scene::Scene& scene, std::uint64_t revision, const ui::UiState& ui, int width, int height,
              bool interacting);
    enum class Next { None, Compiling, Ready };
    // The lane's next program (skipping a preview of a state it already
    // shows): Ready once lane.next holds it, Compiling while it is asked
    // for, None when the lane has no stage left (or its compile failed).
    // During a drag lane.next may be an earlier state's preview, the
    // freshest compiled (lane.nextState says which).
    Next nextProgram(Lane& lane);
    void advance(Lane& lane, bool renders, double budgetSeconds);
    void finishStage(Lane& lane);
    // What one sample of the lane's stage is expected to cost.
    double expectedSecondsPerSample(const Lane& lane, const Stage& stage) const;
    int tileSize(const Lane& lane, const Stage& stage) const;
    SlotView view(Source wanted) const;
    SlotImage slot(Source wanted) const;
    Lane& laneOf(Source source) { return lanes_[static_cast<int>(source)]; }
    const Lane& laneOf(Source source) const { return lanes_[static_cast<int>(source)]; }

    glcontext::GlContext& context_;
    jobs::JobQueue compiles_{1};  // the lanes' scene -> program compiles, one at a time
    std::vector<Lane> lanes_;     // indexed by Source
    DisplayTexture differenceTexture_;
    std::uint64_t differenceState_ = 0;

    // The request being served.
    std::uint64_t requestKey_ = 0;
    std::uint64_t state_ = 0;                    // see view_choice.h
    std::shared_ptr<const scene::Scene> scene_;  // shared with the compiles asked for it
    std::vector<Stage> stages_;
    int width_ = 0, height_ = 0;
    Source wanted_ = Source::Gl;
    bool compare_ = false, heat_ = false, interacting_ = false;
    // The scene of the last full-size stage finished, which waited for its
    // prune grids; whether the current scene's may still be missing.
    std::shared_ptr<const scene::Scene> gridScene_;
    bool gridPending_ = true;
    LanePlan lanePlan_;

    std::optional<image::Comparison> comparison_;
    ViewportStats stats_;
    std::string error_;
};

}  // namespace sdfwb::app::gui
