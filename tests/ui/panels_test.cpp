// The panels without a window (STYLE: test panels headless): an ImGui context
// with a built font atlas runs frames that draw every panel, with each node
// kind selected in turn; drawing alone must never change the scene.

#include <gtest/gtest.h>

#include <imgui.h>

#include "scene/scene_json.h"
#include "scene/scene_validation.h"
#include "support/headless_imgui.h"
#include "support/source_tree.h"
#include "ui/panels.h"

namespace sdfwb::ui {
namespace {

class PanelsTest : public ::testing::Test {
protected:
    test::HeadlessImGui imgui;

    void frame(Editor& editor, UiState& ui) {
        ImGui::NewFrame();
        ImGui::Begin("panels");
        drawSceneTree(editor, ui, [](const NodePath&, const scene::Node&) { return ImTextureID(nullptr); });
        drawInspector(editor, ui);
        drawMaterialsPanel(editor, ui);
        drawLightsPanel(editor, ui);
        drawRenderSettingsPanel(editor, ui);
        drawEnvironmentPanel(editor, ui);
        ImGui::End();
        ImGui::Render();
    }
};

// One node of every kind under the root union (unary kinds wrap a sphere).
scene::Scene everyKind() {
    scene::Scene scene = scene::loadSceneFile(sdfwb::test::sourceDir() + "/scenes/default.json");
    scene.root.children.clear();
    for (const scene::KindSpec& spec : scene::allKinds()) {
        scene::Node node = scene::Node::make(spec.kind);
        if (spec.minChildren > 0) node.children.push_back(scene::Node::make(scene::NodeKind::Sphere));
        scene.root.children.push_back(node);
    }
    return scene;
}

TEST_F(PanelsTest, EveryNodeKindDrawsWithoutEditing) {
    Editor editor(everyKind());
    ASSERT_TRUE(scene::validateScene(editor.scene()).empty());
    UiState ui;
    auto revision = editor.revision();
    frame(editor, ui);
    for (int i = 0; i < scene::kNodeKindCount; ++i) {
        editor.select(NodePath{i});
        frame(editor, ui);
        frame(editor, ui);
    }
    editor.select(std::nullopt);
    frame(editor, ui);
    EXPECT_EQ(editor.revision(), revision);
    EXPECT_FALSE(editor.dirty());
    EXPECT_TRUE(ui.messages.empty());
}

}  // namespace
}  // namespace sdfwb::ui
