#include "app/gui/viewport.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include "program/compile_scene.h"

namespace sdfwb::app::gui {

namespace {
constexpr int kDefaultTileSize = 64;   // pixels per side of one GL draw, before any measurement
constexpr double kDrawBudget = 0.006;  // seconds one GL draw should take at most
constexpr double kPreviewCost = 0.05;  // GPU seconds a preview image should take while interacting
constexpr std::uint64_t kStageTags = 16;  // CPU job tags: plan * 16 + stage

std::uint64_t mix(std::uint64_t seed, std::uint64_t value) {
    return seed ^ (value + 0x9e3779b97f4a7c15ull + (seed << 6) + (seed >> 2));
}
}  // namespace

Viewport::Viewport(glcontext::GlContext& context)
    : context_(context),
      renderer_(context.gl()),
      builder_(context.createShared()),
      cpuJobs_(0),
      glTexture_(context.gl()),
      cpuTexture_(context.gl()),
      differenceTexture_(context.gl()) {}

Viewport::~Viewport() = default;

void Viewport::plan(const scene::Scene& scene, const ui::UiState& ui, int width, int height, bool interacting) {
    planId_++;
    scene_ = scene;
    compare_ = ui.compare != ui::CompareMode::Off;
    useGl_ = ui.backend == ui::ViewBackend::Gl || compare_;
    useCpu_ = ui.backend == ui::ViewBackend::Cpu || compare_;
    glShown_ = useGl_;
    cpuFallback_ = false;
    heat_ = ui.stepHeat;
    width_ = std::max(1, ui.compare == ui::CompareMode::SideBySide ? width / 2 : width);
    height_ = std::max(1, height);
    stages_.clear();
    if (interacting) {
        stages_.push_back({previewScale(), 1});
    } else {
        stages_.push_back({1, 1});
        if (scene.render.aa > 1) stages_.push_back({1, scene.render.aa});
    }
    glStage_ = 0;
    glJob_.reset();
    cpuStage_ = compare_ ? stages_.size() - 1 : 0;
    cpuSubmitted_ = false;
    cpuJobs_.cancelAll();
    glFinal_.reset();
    cpuFinal_.reset();
    comparison_.reset();
    if (useGl_) glTexture_.resize(width_, height_);
    if (useCpu_) cpuTexture_.resize(width_, height_);
}

program::Program Viewport::programFor(const Stage& stage) const {
    program::CompileOptions options;
    options.width = std::max(1, width_ / stage.scale);
    options.height = std::max(1, height_ / stage.scale);
    options.aa = stage.aa;
    return program::compileScene(scene_, options);
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
        plan(scene, ui, width, height, interacting);
    }
    if (useGl_) updateGl(budgetSeconds);
    if (useGl_ && !compare_ && glStage_ == 0 && glWaiting_ && !cpuFallback_) {
        // the last GL image stays up until the CPU's first stage replaces it
        cpuFallback_ = true;
        cpuTexture_.resize(width_, height_);
    }
    if (cpuFallback_ && glStage_ > 0 && error_.empty()) {  // the GL image is complete: it takes over
        cpuFallback_ = false;
        glShown_ = true;
        cpuJobs_.cancelAll();
    }
    if (useCpu_ || cpuFallback_) updateCpu();
    if (cpuFallback_ && glWaiting_) stats_.status = "compiling shader; CPU image meanwhile";
    if (!useGl_ || glStage_ >= stages_.size()) {
        if (!useCpu_ || cpuStage_ >= stages_.size()) stats_.status = error_.empty() ? "done" : "GL shader failed";
    }
}

void Viewport::updateGl(double budgetSeconds) {
    while (std::optional<gl::BuiltProgram> built = builder_.take()) {
        if (built->linked) {
            renderer_.adoptProgram(built->program, std::move(built->linked));
            stats_.compileSeconds = built->seconds;
            stats_.compiles++;
        } else {
            error_ = built->error;
            failedStructure_ = built->program.structureKey();
        }
    }
    if (glStage_ >= stages_.size()) return;
    const Stage& stage = stages_[glStage_];
    try {
        if (!glJob_) {
            program::Program program = programFor(stage);
            if (failedStructure_ == program.structureKey()) {
                glStage_ = stages_.size();  // nothing more to do until the structure changes
                return;
            }
            glWaiting_ = !renderer_.hasProgram(program);
            if (glWaiting_) {
                builder_.request(program);
                stats_.status = "compiling shader";
                return;
            }
            error_.clear();
            glJob_ = std::make_unique<gl::ProgressiveRender>(renderer_, std::move(program), tileSize());
        }
        for (const gl::TileRect& tile : glJob_->advance(budgetSeconds)) {
            glTexture_.upload(glJob_->frame(), tile, stage.scale, heat_, scene_.render.maxSteps);
        }
        stats_.status = "GL: rendering " + std::to_string(static_cast<int>(glJob_->progress() * 100)) + "%" +
                        (stage.scale > 1 ? " (preview)" : " at AA " + std::to_string(stage.aa));
        if (glJob_->done()) {
            const program::Program& done = glJob_->program();
            double samples = static_cast<double>(done.width) * done.height * done.aa * done.aa;
            double gpu = glJob_->gpuSeconds() > 0 ? glJob_->gpuSeconds() : glJob_->drawSeconds();
            secondsPerSample_ = gpu / std::max(1.0, samples);
            stats_.gpuSeconds = glJob_->gpuSeconds();
            finishStage(glJob_->frame(), glJob_->drawSeconds(), stage, true);
            glJob_.reset();
            ++glStage_;
        }
    } catch (const std::exception& error) {
        error_ = error.what();
        glJob_.reset();
        glStage_ = stages_.size();
    }
}

int Viewport::previewScale() const {
    // the largest preview whose cost, as measured on the last GL stage, is
    // about kPreviewCost; at least half resolution
    double pixels = static_cast<double>(width_) * height_;
    if (secondsPerSample_ <= 0 || pixels <= 0) return 4;
    double scale = std::ceil(std::sqrt(pixels * secondsPerSample_ / kPreviewCost));
    return std::clamp(static_cast<int>(scale), 2, 16);
}

int Viewport::tileSize() const {
    if (secondsPerSample_ <= 0) return kDefaultTileSize;
    // a square tile whose single sub-sample pass costs about kDrawBudget
    int side = static_cast<int>(std::sqrt(kDrawBudget / secondsPerSample_));
    return std::clamp(side / 16 * 16, 16, 256);
}

void Viewport::updateCpu() {
    for (CpuResult& result : cpuJobs_.takeResults()) {
        if (cpuStage_ >= stages_.size() || result.tag != planId_ * kStageTags + cpuStage_) continue;
        const Stage& stage = stages_[cpuStage_];
        gl::TileRect all{0, 0, result.frame.color.width, result.frame.color.height};
        cpuTexture_.upload(result.frame, all, stage.scale, heat_, scene_.render.maxSteps);
        if (cpuFallback_) glShown_ = false;
        finishStage(result.frame, result.seconds, stage, false);
        ++cpuStage_;
        cpuSubmitted_ = false;
    }
    if (cpuStage_ < stages_.size()) {
        if (!cpuSubmitted_) {
            cpuJobs_.submit({planId_ * kStageTags + cpuStage_, programFor(stages_[cpuStage_])}, true);
            cpuSubmitted_ = true;
        }
        if (!useGl_ || glStage_ >= stages_.size() || cpuFallback_) {
            stats_.status = "CPU: rendering " + std::to_string(static_cast<int>(cpuJobs_.progress() * 100)) + "%";
        }
    }
}

void Viewport::finishStage(const image::Frame& frame, double seconds, const Stage& stage, bool gl) {
    // a GL stage finishing while the CPU stands in is the image that takes
    // over (update() swaps them next): its figures are the ones to show
    if (gl == glShown_ || (gl && cpuFallback_)) {
        if (!gl) stats_.gpuSeconds = 0;
        stats_.width = frame.color.width;
        stats_.height = frame.color.height;
        stats_.aa = stage.aa;
        stats_.renderSeconds = seconds;
        stats_.frame = image::frameStats(frame);
    }
    if (&stage != &stages_.back()) return;
    (gl ? glFinal_ : cpuFinal_) = frame;
    if (compare_ && glFinal_ && cpuFinal_) {
        comparison_ = image::compareImages(glFinal_->color, cpuFinal_->color);
        differenceTexture_.upload(image::differenceHeatImage(glFinal_->color, cpuFinal_->color));
    }
}

bool Viewport::idle() const {
    if (requestKey_ == 0) return false;  // nothing requested yet: the first frame is still to come
    bool glDone = !useGl_ || glStage_ >= stages_.size();
    bool cpuDone = !useCpu_ || cpuStage_ >= stages_.size();
    bool compareDone = !compare_ || comparison_.has_value() || !error_.empty();
    return glDone && cpuDone && compareDone && !builder_.busy();
}

}  // namespace sdfwb::app::gui
