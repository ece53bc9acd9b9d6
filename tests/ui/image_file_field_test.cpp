// The image file fields of the materials and environment panels
// (ui/image_file_field.h), drawn headless: the image check reads the files
// off the UI thread and leaves a thumbnail of each readable one, which the
// fields ask the window for by their JSON paths; drawing changes nothing.

#include <set>

#include <gtest/gtest.h>

#include <imgui.h>

#include "image/image_io.h"
#include "support/headless_imgui.h"
#include "support/scratch_folder.h"
#include "ui/panels.h"

namespace sdfwb::ui {
namespace {

class ImageFileField : public ::testing::Test {
protected:
    test::HeadlessImGui imgui;
    test::ScratchFolder folder;

    void frame(Editor& editor, UiState& ui) {
        ImGui::NewFrame();
        ImGui::Begin("panels");
        drawMaterialsPanel(editor, ui);
        drawEnvironmentPanel(editor, ui);
        ImGui::End();
        ImGui::Render();
    }

    scene::Scene texturedScene() {
        image::writeImage(folder / "grid.png", image::Image(8, 8));
        scene::Scene s;
        s.directory.path = folder.path().string();
        scene::Material wood;
        wood.name = "wood";
        wood.texture = scene::TexturePattern::Image;
        wood.textureImage = "grid.png";
        scene::Material missing = wood;
        wood.bump = scene::BumpPattern::Image;
        wood.bumpImage = "grid.png";
        missing.name = "missing";
        missing.textureImage = "missing.png";
        s.materials = {wood, missing};
        s.environment.map = scene::EnvironmentMapKind::Equirect;
        s.environment.image = "grid.png";
        return s;
    }
};

TEST_F(ImageFileField, EachReadableFileGetsAThumbnailBesideItsField) {
    Editor editor(texturedScene());
    UiState ui;
    std::set<std::string> asked;
    ui.imageThumbnail = [&](const std::string& key) {
        asked.insert(key);
        return ui.imageCheck->previews().count(key) ? reinterpret_cast<void*>(1) : nullptr;
    };
    auto revision = editor.revision();
    frame(editor, ui);  // requests the check
    ui.imageCheck->wait();
    frame(editor, ui);
    EXPECT_EQ(asked, (std::set<std::string>{"environment.image", "materials[0].texture_image",
                                            "materials[0].bump_image", "materials[1].texture_image"}));
    std::map<std::string, image::Image> previews = ui.imageCheck->previews();
    EXPECT_EQ(previews.size(), 3u);  // the missing file has none, only its problem
    EXPECT_EQ(previews.at("materials[0].texture_image").width, 8);
    ASSERT_EQ(ui.imageCheck->problems().size(), 1u);
    EXPECT_EQ(ui.imageCheck->problems()[0].rfind("materials[1].texture_image: cannot read image", 0), 0u);
    EXPECT_GT(ui.imageCheck->previewGeneration(), 0u);
    EXPECT_EQ(editor.revision(), revision);
    EXPECT_FALSE(editor.dirty());
}

}  // namespace
}  // namespace sdfwb::ui
