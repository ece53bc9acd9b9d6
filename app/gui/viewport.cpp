#include "app/gui/viewport.h"

#include <algorithm>
#include <cmath>

#include "cpu/cpu_backend.h"
#include "gl/gl_backend.h"
#include "gl/progressive_render.h"
#include "program/compile_scene.h"
#include "prune/grid_edits.h"

namespace sdfwb::app::gui {

namespace {
constexpr int kDefaultTileSize = 64;   // pixels per side of one GL draw, before any measurement
constexpr double kDrawBudget = 0.006;  // seconds one GL draw should take at most

std::uint64_t mix(std::uint64_t seed, std::uint64_t value) {
    return seed ^ (value + 0x9e3779b97f4a7c15ull + (seed << 6) + (seed >> 2));
}

const char* sourceName(Source source) { return source == Source::Gl ? "GLSL" : "CPU"; }
}  // namespace

Viewport::Viewport(glcontext::GlContext& context) : context_(context), differenceTexture_(context.gl()) {
    // The one place the viewport names its backends: the GL backend builds
    // programs on a worker with a context sharing the window's.
    lanes_.reserve(kSources);
    lanes_.emplace_back(Source::Gl, std::make_unique<gl::GlBackend>(context, context.createShared()), context.gl(),
                        compiles_);
    lanes_.emplace_back(Source::Cpu, std::make_unique<cpu::CpuBackend>(), context.gl(), compiles_);
}

Viewport::~Viewport() = default;

void Viewport::plan(const scene::Scene& scene, std::uint64_t revision, const ui::UiState& ui, int width, int height,
                    bool interacting) {
    scene_ = std::make_shared<const scene::Scene>(scene);
    gridPending_ = !gridScene_ || !prune::keepsPruneGrids(*gridScene_, scene);
    compare_ = ui.compare != ui::CompareMode::Off;
    wanted_ = ui.backend == ui::ViewBackend::Gl ? Source::Gl : Source::Cpu;
    heat_ = ui.stepHeat;
    interacting_ = interacting;
    width_ = std::max(1, ui.compare == ui::CompareMode::SideBySide ? width / 2 : width);
    height_ = std::max(1, height);
    // never 0, which means "nothing" in ImageContent
    state_ = std::max<std::uint64_t>(1, mix(mix(mix(revision, width_), height_), heat_));
    stages_.clear();
    stages_.push_back({true, 1});
    if (!interacting) {
        stages_.push_back({false, 1});
        if (scene.render.aa > 1) stages_.push_back({false, scene.render.aa});
    }
    for (Lane& lane : lanes_) {
        lane.job.reset();
        lane.next.reset();
        lane.stage = 0;
        lane.final.reset();
        lane.texture.resize(width_, height_);
    }
    comparison_.reset();
}

void Viewport::update(const scene::Scene& scene, std::uint64_t revision, const ui::UiState& ui, int width, int height,
                      bool interacting, double budgetSeconds) {
    std::uint64_t key = revision;
    for (std::uint64_t v : {std::uint64_t(ui.backend), std::uint64_t(ui.compare), std::uint64_t(ui.stepHeat),
                            std::uint64_t(width), std::uint64_t(height), std::uint64_t(interacting)}) {
        key = mix(key, v);
    }
    if (key != requestKey_) {
        requestKey_ = key;
        plan(scene, revision, ui, width, height, interacting);
    }

    // Whether the GL backend can render its next stage now decides whether
    // the CPU stands in (view_choice.h: planLanes). While the GL lane's
    // program is still compiling nothing is known yet: no stand-in for that
    // (the CPU lane would wait for the same compile).
    Lane& gl = laneOf(Source::Gl);
    bool glReady = true, glFailed = false, compiling = false;
    if ((wanted_ == Source::Gl || compare_) && !gl.job) {
        Next next = nextProgram(gl);
        compiling = next == Next::Compiling;
        if (next == Next::Ready) {
            render::Readiness readiness = gl.backend->readiness(*gl.next);
            glReady = readiness.ready;
            glFailed = !readiness.error.empty();
            if (glFailed) error_ = readiness.error;
        }
    }
    lanePlan_ = planLanes(wanted_, compare_, glReady, glFailed);
    stats_.compiles = gl.backend->builds();
    stats_.compileSeconds = gl.backend->lastPrepareSeconds();

    stats_.status.clear();
    for (Lane& lane : lanes_) advance(lane, lanePlan_.renders[static_cast<int>(lane.source)], budgetSeconds);
    if (stats_.status.empty()) {
        if (compiling) {
            stats_.status = "compiling the scene";
        } else if (!glReady && !glFailed) {
            stats_.status = "compiling shader";
        } else {
            stats_.status = error_.empty() ? "done" : "GL shader failed";
        }
    }
    if (lanePlan_.standIn && !glReady && !glFailed) stats_.status = "compiling shader; CPU image meanwhile";
}

std::string Viewport::errorLine() const {
    constexpr std::string_view kBackend = "GL backend: ";
    return (error_.starts_with(kBackend) ? error_ : std::string(kBackend) + error_) + " (the CPU backend still works)";
}

Viewport::Next Viewport::nextProgram(Lane& lane) {
    if (lane.next) return Next::Ready;
    // a preview of a state the texture already shows is not worth drawing
    if (lane.stage < stages_.size() && stages_[lane.stage].preview && lane.content.state == state_) ++lane.stage;
    if (lane.stage >= stages_.size()) return Next::None;
    const Stage& stage = stages_[lane.stage];
    int scale =
        stage.preview ? previewScale(static_cast<double>(width_) * height_, expectedSecondsPerSample(lane, stage)) : 1;
    program::CompileOptions options;
    options.width = std::max(1, width_ / scale);
    options.height = std::max(1, height_ / scale);
    options.aa = stage.aa;
    // asked again each frame until ready: the same request does nothing,
    // and a new state's supersedes the compile of an older one
    LaneCompile wanted{state_, lane.stage, scale};
    lane.compiler->request(scene_, options, wanted);
    if (std::optional<ui::ProgramCompiler<LaneCompile>::Compiled> compiled = lane.compiler->take()) {
        // chooseSlot shows a drag's preview without a note while interacting, as outdated after
        const LaneCompile& made = compiled->tag;
        const program::Program& program = compiled->program;
        bool fits =
            program.width == std::max(1, width_ / made.scale) && program.height == std::max(1, height_ / made.scale);
        if (drawsCompiled(made == wanted, made.state, lane.content.state, interacting_, fits)) {
            lane.next = std::move(compiled->program);
            lane.scale = made.scale;
            lane.nextState = made.state;
            return Next::Ready;
        }
    }
    if (std::string failed = lane.compiler->error(); !failed.empty()) {
        error_ = failed;
        lane.stage = stages_.size();
        return Next::None;
    }
    return Next::Compiling;
}

void Viewport::advance(Lane& lane, bool renders, double budgetSeconds) {
    if (!renders) {
        lane.job.reset();  // a stand-in no longer needed: its cores go to the backend that is ready
        lane.compiler->cancel();
        return;
    }
    if (!lane.job) {
        Next next = nextProgram(lane);
        if (next == Next::Compiling) stats_.status = std::string(sourceName(lane.source)) + ": compiling the scene";
        if (next != Next::Ready) return;
        render::Readiness readiness = lane.backend->readiness(*lane.next);
        if (!readiness.ready) return;
        if (lane.source == Source::Gl) error_.clear();
        const Stage& stage = stages_[lane.stage];
        render::RenderControl control;
        control.tileSize = tileSize(lane, stage);
        // a preview of a large scene is drawn before its grid is built
        control.waitForPruneGrid = !stage.preview;
        lane.rendersWhole = stage.preview && gridPending_;
        try {
            lane.job = lane.backend->startProgressive(*lane.next, control);
        } catch (const std::exception& error) {
            error_ = error.what();
            lane.stage = stages_.size();
            return;
        }
    }
    try {
        for (const render::TileRect& tile : lane.job->advance(budgetSeconds)) {
            if (refinesInPlace(lane.content, lane.nextState)) {
                lane.texture.upload(lane.job->frame(), tile, lane.scale, heat_, scene_->render.maxSteps);
            }
        }
    } catch (const std::exception& error) {
        error_ = error.what();
        lane.job.reset();
        lane.stage = stages_.size();
        return;
    }
    if (lane.job->done()) {
        finishStage(lane);
        return;
    }
    const Stage& stage = stages_[lane.stage];
    stats_.status = std::string(sourceName(lane.source)) + ": rendering " +
                    std::to_string(static_cast<int>(lane.job->progress() * 100)) + "%" +
                    (stage.preview ? " (preview)" : " at AA " + std::to_string(stage.aa));
}

void Viewport::finishStage(Lane& lane) {
    const render::ProgressiveRender& job = *lane.job;
    const image::Frame& frame = job.frame();
    if (!refinesInPlace(lane.content, lane.nextState)) {
        // the tiles waited: the finished image replaces one of another state at once
        lane.texture.upload(frame, {0, 0, frame.color.width, frame.color.height}, lane.scale, heat_,
                            scene_->render.maxSteps);
    }
    lane.content = {lane.nextState, static_cast<int>(lane.stage)};
    // an earlier state's preview drawn during a drag: the current state's stage is still to do
    bool current = lane.nextState == state_;
    const program::Program& done = job.program();
    double samples = static_cast<double>(done.width) * done.height * done.aa * done.aa;
    double seconds = job.deviceSeconds() > 0 ? job.deviceSeconds() : job.seconds();
    lane.secondsPerSample = seconds / std::max(1.0, samples);
    if (lane.rendersWhole) lane.secondsPerWholeSample = lane.secondsPerSample;
    if (lane.source == view(compare_ ? Source::Gl : wanted_).shown) {
        stats_.width = frame.color.width;
        stats_.height = frame.color.height;
        stats_.aa = done.aa;
        stats_.renderSeconds = job.seconds();
        stats_.gpuSeconds = job.deviceSeconds();
        stats_.frame = image::frameStats(frame);
    }
    if (current && lane.stage + 1 == stages_.size()) {
        lane.final = frame;
        const Lane& gl = laneOf(Source::Gl);
        const Lane& cpu = laneOf(Source::Cpu);
        if (compare_ && gl.final && cpu.final) {
            comparison_ = image::compareImages(gl.final->color, cpu.final->color);
            differenceTexture_.resize(width_, height_);
            differenceTexture_.upload(image::differenceHeatImage(gl.final->color, cpu.final->color));
            differenceState_ = state_;
        }
    }
    if (current && !stages_[lane.stage].preview) {
        gridScene_ = scene_;
        gridPending_ = false;
    }
    if (current) ++lane.stage;
    lane.next.reset();
    lane.job.reset();
}

double Viewport::expectedSecondsPerSample(const Lane& lane, const Stage& stage) const {
    if (!stage.preview) return lane.secondsPerSample;
    return previewSecondsPerSample(lane.secondsPerSample, lane.secondsPerWholeSample, gridPending_);
}

int Viewport::tileSize(const Lane& lane, const Stage& stage) const {
    if (lane.source != Source::Gl) return 0;  // the CPU backend's default: its tiles run on workers
    double price = expectedSecondsPerSample(lane, stage);
    if (price <= 0) return kDefaultTileSize;
    // a square tile whose single sub-sample pass costs about kDrawBudget
    int side = static_cast<int>(std::sqrt(kDrawBudget / price));
    return std::clamp(side / gl::kMinTileSize * gl::kMinTileSize, gl::kMinTileSize, 256);
}

SlotView Viewport::view(Source wanted) const {
    const ImageContent contents[kSources] = {laneOf(Source::Gl).content, laneOf(Source::Cpu).content};
    return chooseSlot(wanted, contents, state_, interacting_);
}

SlotImage Viewport::slot(Source wanted) const {
    SlotView view = this->view(wanted);
    SlotImage image{&laneOf(view.shown).texture, ""};
    switch (view.note) {
    case SlotView::Note::None: break;
    case SlotView::Note::StandIn:
        image.note = std::string(sourceName(view.shown)) + " image until the " + sourceName(wanted) + " one is ready";
        break;
    case SlotView::Note::Outdated: image.note = "outdated: an earlier state, rendering the current one"; break;
    case SlotView::Note::Empty: image.note = "rendering"; break;
    }
    return image;
}

SlotImage Viewport::difference() const {
    if (differenceState_ == state_) return {&differenceTexture_, ""};
    return {&differenceTexture_, differenceState_ == 0 ? "waiting for both backends" : "outdated: an earlier state"};
}

bool Viewport::idle() const {
    if (requestKey_ == 0) return false;  // nothing requested yet: the first frame is still to come
    for (const Lane& lane : lanes_) {
        if (lanePlan_.renders[static_cast<int>(lane.source)] && lane.stage < stages_.size()) return false;
    }
    bool compareDone = !compare_ || comparison_.has_value() || !error_.empty();
    return compareDone && laneOf(Source::Gl).backend->buildsIdle();
}

}  // namespace sdfwb::app::gui
