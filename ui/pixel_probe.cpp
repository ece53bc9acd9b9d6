#include "ui/pixel_probe.h"

#include <algorithm>
#include <cstdio>

#include "program/compile_scene.h"
#include "ui/node_path.h"

namespace sdfwb::ui {

std::shared_ptr<const program::Program> PickPrograms::get(const scene::Scene& scene, std::uint64_t revision, int width,
                                                          int height) {
    std::lock_guard lock(mutex_);  // a second probe's worker waits for this compile instead of repeating it
    if (!program_ || revision_ != revision || width_ != width || height_ != height) {
        program_ = std::make_shared<const program::Program>(program::compileScene(scene, {width, height, 1}));
        revision_ = revision, width_ = width, height_ = height;
        ++compiles_;
    }
    return program_;
}

int PickPrograms::compiles() const {
    std::lock_guard lock(mutex_);
    return compiles_;
}

void PixelProbe::request(const scene::Scene& scene, std::uint64_t revision, int width, int height, double x, double y) {
    Requested next{revision, std::max(width, 1), std::max(height, 1), x, y};
    if (requested_ == next) return;
    if (!scene_ || !requested_ || requested_->revision != revision)
        scene_ = std::make_shared<const scene::Scene>(scene);
    requested_ = next;
    if (job_ && !job_->started()) job_->cancel();  // superseded before it ran
    job_ = queue_.submit([shared = shared_, programs = programs_, scene = scene_, next](jobs::Job&) {
        std::shared_ptr<const program::Program> program = programs->get(*scene, next.revision, next.width, next.height);
        PixelReading reading{next.revision, next.width, next.height,
                             next.x,        next.y,     cpu::pickPixel(*scene, *program, next.x, next.y)};
        std::lock_guard lock(shared->mutex);
        shared->latest = std::move(reading);
    });
}

std::optional<PixelReading> PixelProbe::latest() const {
    std::lock_guard lock(shared_->mutex);
    return shared_->latest;
}

bool PixelProbe::pending() const { return job_ && !job_->finished(); }

void PixelProbe::wait() const {
    if (job_) job_->wait();
}

std::string readoutText(const cpu::PickResult& pick) {
    std::string text = "steps " + std::to_string(pick.steps) + "   ";
    if (!pick.hit) return text + "no hit";
    char numbers[96];
    std::snprintf(numbers, sizeof numbers, "distance %.4g at (%.3f, %.3f, %.3f)   ", pick.distance, pick.position.x,
                  pick.position.y, pick.position.z);
    text += numbers;
    return text + (pick.ground ? std::string("ground") : pick.node ? formatNodePath(*pick.node) : std::string("?"));
}

}  // namespace sdfwb::ui
