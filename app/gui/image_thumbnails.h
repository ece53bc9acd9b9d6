#pragma once
// Thumbnails of the scene's image files (the materials' textures and the
// environment map's images) beside their fields in the materials and
// environment panels. The image check (ui/scene_image_check.h) makes them on
// its worker with the problems it finds; this uploads each finished set once.

#include <cstdint>
#include <map>
#include <memory>
#include <string>

#include "app/gui/display_texture.h"
#include "ui/scene_image_check.h"

namespace sdfwb::app::gui {

class ImageThumbnails {
public:
    explicit ImageThumbnails(const glcontext::GlFunctions& gl) : gl_(gl) {}

    // Uploads the check's thumbnails when they changed since the last call.
    void update(const ui::SceneImageCheck& check);
    // The thumbnail of the file named at JSON path `key`; null when it has none.
    void* lookup(const std::string& key) const;

private:
    const glcontext::GlFunctions& gl_;
    std::uint64_t generation_ = 0;
    std::map<std::string, std::unique_ptr<DisplayTexture>> textures_;
};

}  // namespace sdfwb::app::gui
