#pragma once
// The check of the scene's image files (the environment map's and the
// textures') off the UI thread: reading an image (and, for a bad one, finding
// which of the box map's six it is) can take a noticeable moment, so the
// check runs on a worker whenever the files the scene names change, and the
// panels show the last finished answer under each field, with a thumbnail
// of each image that can be read. Its job also leaves
// the images in the image cache (image/mipmapped_images.h), so the
// viewport's next render finds them read.

#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "image/image.h"
#include "jobs/job_queue.h"
#include "scene/scene.h"

namespace sdfwb::ui {

class SceneImageCheck {
public:
    // Checks the image files `scene` names unless they are the ones last
    // asked about; returns at once.
    void request(const scene::Scene& scene);
    // The last finished check's problems ("environment.image: cannot read ...",
    // "materials[1].texture_image: ...").
    std::vector<std::string> problems() const;
    // The last finished check's thumbnails (program::sceneImagePreviews, at
    // most kPreviewSide square), by key, and a count that changes whenever they do.
    std::map<std::string, image::Image> previews() const;
    std::uint64_t previewGeneration() const;
    static constexpr int kPreviewSide = 64;
    // The last request's check is still running.
    bool pending() const { return job_ && !job_->finished(); }
    // Waits for the last request (tests; the UI polls).
    void wait() const {
        if (job_) job_->wait();
    }

private:
    struct Shared {
        mutable std::mutex mutex;
        std::vector<std::string> problems;
        std::map<std::string, image::Image> previews;
        std::uint64_t generation = 0;
    };
    std::vector<std::string> asked_;  // the files last asked about, with their keys
    std::shared_ptr<Shared> shared_ = std::make_shared<Shared>();
    jobs::JobHandle job_;
    jobs::JobQueue queue_{1};  // last: stops before the rest goes
};

}  // namespace sdfwb::ui
