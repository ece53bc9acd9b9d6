#include "app/gui/image_thumbnails.h"

namespace sdfwb::app::gui {

void ImageThumbnails::update(const ui::SceneImageCheck& check) {
    if (check.previewGeneration() == generation_) return;
    generation_ = check.previewGeneration();
    std::map<std::string, std::unique_ptr<DisplayTexture>> textures;
    for (const auto& [key, preview] : check.previews()) {
        auto& texture = textures[key];
        auto old = textures_.find(key);
        texture = old != textures_.end() ? std::move(old->second) : std::make_unique<DisplayTexture>(gl_);
        texture->upload(preview);
    }
    textures_ = std::move(textures);
}

void* ImageThumbnails::lookup(const std::string& key) const {
    auto found = textures_.find(key);
    return found == textures_.end() ? nullptr : found->second->id();
}

}  // namespace sdfwb::app::gui
