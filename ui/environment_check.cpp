#include "ui/environment_check.h"

#include "program/environment.h"

namespace sdfwb::ui {

void EnvironmentCheck::request(const scene::Scene& scene) {
    std::vector<std::string> asked;
    for (const program::EnvironmentFile& file : program::environmentFiles(scene)) {
        asked.push_back(file.key + "=" + file.name + "=" + file.path.string());
    }
    if (job_ && asked == asked_) return;
    asked_ = asked;
    if (job_ && !job_->started()) job_->cancel();
    // the environment alone: the job needs nothing else of the scene
    auto checked = std::make_shared<scene::Scene>();
    checked->environment = scene.environment;
    checked->directory = scene.directory;
    job_ = queue_.submit([checked, shared = shared_](jobs::Job&) {
        std::vector<std::string> problems = program::environmentProblems(*checked);
        std::lock_guard lock(shared->mutex);
        shared->problems = std::move(problems);
    });
}

std::vector<std::string> EnvironmentCheck::problems() const {
    std::lock_guard lock(shared_->mutex);
    return shared_->problems;
}

}  // namespace sdfwb::ui
