#include "app/gui/thumbnails.h"

#include <functional>

#include "cpu/cpu_renderer.h"
#include "ui/view_camera.h"
#include "program/compile_scene.h"
#include "scene/scene_json.h"

namespace sdfwb::app::gui {

Thumbnails::Thumbnails(const glcontext::GlFunctions& gl) : gl_(gl) {}

void* Thumbnails::lookup(const scene::Scene& scene, std::uint64_t revision, const ui::NodePath& path,
                         const scene::Node& node) {
    auto previous = shown_.find(path);
    if (paused_) {
        // no hashing or queueing while the user drags: the last images stay
        return previous == shown_.end() ? nullptr : textures_.at(previous->second)->id();
    }
    if (revision != revision_) {
        revision_ = revision;
        keys_.clear();
        // renders for the previous state are stale: requested again if still shown
        jobs_.cancelAll();
        pending_.clear();
        requested_.clear();
        nlohmann::ordered_json look = scene::sceneToJson(scene);
        look.erase("root");
        look.erase("camera");
        look.erase("name");
        look.erase("description");
        lookHash_ = std::hash<std::string>{}(look.dump());
    }
    auto known = keys_.find(path);
    std::uint64_t key = known != keys_.end()
                            ? known->second
                            : (keys_[path] = std::hash<std::string>{}(scene::nodeToJson(node).dump()) ^ (lookHash_ * 31));
    if (auto texture = textures_.find(key); texture != textures_.end()) {
        shown_[path] = key;
        return texture->second->id();
    }
    if (requested_.insert(key).second) {
        // the subtree alone with what lights it (not a copy of the whole tree per row)
        scene::Scene alone;
        alone.render = scene.render;
        alone.environment = scene.environment;
        alone.lights = scene.lights;
        alone.materials = scene.materials;
        alone.directory = scene.directory;  // image files are named relative to it
        alone.root = node;
        alone.environment.ground.enabled = false;
        alone.camera = ui::framedCamera(scene.camera, node);
        alone.render.aa = 1;
        program::CompileOptions options{kSize, kSize, 1};
        auto frame = std::make_shared<image::Frame>();
        // compiled on the worker with the render: a subtree's compile (its
        // prune grid) is not the UI thread's to pay
        jobs::JobHandle job = jobs_.submit([alone = std::move(alone), options, frame](jobs::Job& job) {
            program::Program program = program::compileScene(alone, options);
            if (job.cancelled()) return;  // superseded by a newer state while compiling
            render::RenderControl control;
            control.threads = 1;  // a thumbnail is small: leave the other cores to the viewport
            control.cancel = &job.cancelFlag();
            *frame = cpu::renderCpu(program, control).frame;
        });
        pending_.push_back({key, std::move(job), std::move(frame)});
    }
    return previous == shown_.end() ? nullptr : textures_.at(previous->second)->id();
}

void Thumbnails::update(bool paused) {
    paused_ = paused;
    jobs_.setPaused(paused);
    std::erase_if(pending_, [&](const Pending& p) {
        if (!p.job->finished()) return false;
        if (!p.job->cancelled()) {
            auto texture = std::make_unique<DisplayTexture>(gl_);
            texture->upload(p.frame->color);
            textures_[p.key] = std::move(texture);
        }
        return true;
    });
}

}  // namespace sdfwb::app::gui
