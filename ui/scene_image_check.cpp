#include "ui/scene_image_check.h"

#include "program/scene_images.h"

namespace sdfwb::ui {

void SceneImageCheck::request(const scene::Scene& scene) {
    std::vector<std::string> asked;
    for (const auto& files : {program::environmentFiles(scene), program::textureFiles(scene)}) {
        for (const program::SceneImageFile& file : files) {
            asked.push_back(file.key + "=" + file.name + "=" + file.path.string());
        }
    }
    if (job_ && asked == asked_) return;
    asked_ = asked;
    if (job_ && !job_->started()) job_->cancel();
    // the environment and materials alone: the job needs nothing else of the scene
    auto checked = std::make_shared<scene::Scene>();
    checked->environment = scene.environment;
    checked->materials = scene.materials;
    checked->directory = scene.directory;
    job_ = queue_.submit([checked, shared = shared_](jobs::Job&) {
        std::vector<std::string> problems = program::sceneImageProblems(*checked);
        std::map<std::string, image::Image> previews = program::sceneImagePreviews(*checked, kPreviewSide);
        std::lock_guard lock(shared->mutex);
        shared->problems = std::move(problems);
        shared->previews = std::move(previews);
        ++shared->generation;
    });
}

std::vector<std::string> SceneImageCheck::problems() const {
    std::lock_guard lock(shared_->mutex);
    return shared_->problems;
}

std::map<std::string, image::Image> SceneImageCheck::previews() const {
    std::lock_guard lock(shared_->mutex);
    return shared_->previews;
}

std::uint64_t SceneImageCheck::previewGeneration() const {
    std::lock_guard lock(shared_->mutex);
    return shared_->generation;
}

}  // namespace sdfwb::ui
