#pragma once
// Small renders of each tree node's subtree, as the thesis's node editor gave
// every node its own canvas. Compiled and rendered by the CPU backend on a
// worker thread (a thumbnail is too small to pay for a shader compile per
// subtree; the UI thread only copies the subtree and queues it), cached
// by a hash of the subtree and of what lights it, paused while the user drags.

#include <cstdint>
#include <map>
#include <memory>
#include <set>
#include <vector>

#include "app/gui/display_texture.h"
#include "jobs/job_queue.h"
#include "scene/scene.h"
#include "ui/node_path.h"

namespace sdfwb::app::gui {

class Thumbnails {
public:
    static constexpr int kSize = 48;  // pixels per side

    explicit Thumbnails(const glcontext::GlFunctions& gl);

    // The subtree's texture (null until rendered); queues a render when missing.
    // `revision` identifies the scene state (the hashes are kept per revision).
    void* lookup(const scene::Scene& scene, std::uint64_t revision, const ui::NodePath& path,
                 const scene::Node& node);
    // Uploads finished renders; while `paused`, queued renders wait and
    // lookups show the last images without hashing or queueing anything.
    void update(bool paused);
    // No thumbnail render is queued or running.
    bool idle() const { return !jobs_.busy(); }

private:
    struct Pending {
        std::uint64_t key = 0;
        jobs::JobHandle job;
        std::shared_ptr<image::Frame> frame;  // written by the job
    };

    const glcontext::GlFunctions& gl_;
    std::vector<Pending> pending_;
    std::map<std::uint64_t, std::unique_ptr<DisplayTexture>> textures_;
    std::set<std::uint64_t> requested_;
    bool paused_ = false;
    std::uint64_t revision_ = 0;
    std::uint64_t lookHash_ = 0;  // materials, lights, environment
    std::map<ui::NodePath, std::uint64_t> keys_;
    // The texture last shown at each path: shown until the new one is ready.
    std::map<ui::NodePath, std::uint64_t> shown_;
    jobs::JobQueue jobs_{1};  // last: stops before what its jobs write into
};

}  // namespace sdfwb::app::gui
