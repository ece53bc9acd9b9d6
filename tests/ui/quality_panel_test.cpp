// The quality presets and the error estimate draw without a window and edit nothing by themselves.

#include <gtest/gtest.h>

#include "support/headless_imgui.h"
#include "ui/quality_panel.h"

namespace sdfwb::ui {
namespace {

void frame(Editor& editor, UiState& ui, const tradeoff::SceneMeasurements* measured) {
    ImGui::NewFrame();
    ImGui::Begin("render");
    drawQualityPresets(editor, ui, measured);
    ImGui::End();
    ImGui::Render();
}

TEST(QualityPanel, DrawsWithAndWithoutMeasurementsAndLeavesTheSceneAlone) {
    test::HeadlessImGui imgui;
    Editor editor(scene::Scene{});
    UiState ui;
    auto revision = editor.revision();
    frame(editor, ui, nullptr);
    tradeoff::SceneMeasurements measured{{"cpu"}, {{editor.scene().render, {1.0}, 0.5}}};
    frame(editor, ui, &measured);
    EXPECT_EQ(editor.revision(), revision);
}

}  // namespace
}  // namespace sdfwb::ui
