// The problems list (issue 13, item 8): errors tied to their cause, resolved
// when the cause is fixed (not by unrelated edits), a newer error of the same
// cause replacing the older, and the way to the cause.

#include <gtest/gtest.h>

#include "scene/scene_json.h"
#include "support/source_tree.h"
#include "ui/panels.h"
#include "ui/problems.h"

namespace sdfwb::ui {
namespace {

scene::Scene defaultScene() { return scene::loadSceneFile(sdfwb::test::sourceDir() + "/scenes/default.json"); }

TEST(Problems, TheCauseIsTheJsonPathAMessageStartsWith) {
    std::optional<ProblemCause> node = problemCause("root.children[0].children[0].radius: must be > 0 (got -1)");
    ASSERT_TRUE(node);
    EXPECT_EQ(node->jsonPath, "root.children[0].children[0].radius");
    EXPECT_EQ(node->node, (NodePath{0, 0}));
    EXPECT_EQ(node->tab, InspectorTab::Node);
    std::optional<ProblemCause> setting = problemCause("render.aa: must be a whole number from 1 to 8 (got 99)");
    ASSERT_TRUE(setting);
    EXPECT_EQ(setting->node, std::nullopt);
    EXPECT_EQ(setting->tab, InspectorTab::Render);
    EXPECT_EQ(problemCause("lights[1].softness: must be > 0")->tab, InspectorTab::Lights);
    EXPECT_EQ(problemCause("demo.txt:4: unknown command"), std::nullopt);
    EXPECT_EQ(problemCause("scenes/x.json: root.children[0]: missing node kind"), std::nullopt);
    EXPECT_EQ(problemCause("no cause here"), std::nullopt);
}

TEST(Problems, AnErrorIsResolvedWhenItsCauseIsFixedNotByOtherEdits) {
    Editor editor(defaultScene());
    UiState ui;
    reportProblems(ui, editor.setField({0, 0}, "radius", -1.0));
    updateProblems(ui, editor);
    ASSERT_EQ(openErrors(ui).size(), 1u);
    ASSERT_TRUE(editor.setField({1, 0, 0}, "half_extents", glm::dvec3(0.5)).empty());  // unrelated
    updateProblems(ui, editor);
    EXPECT_EQ(openErrors(ui).size(), 1u);
    ASSERT_TRUE(editor.setField({0, 0}, "radius", 0.5).empty());  // the fix
    updateProblems(ui, editor);
    EXPECT_TRUE(openErrors(ui).empty());
}

TEST(Problems, ANewerErrorOfTheSameCauseReplacesTheOlderAndADeletedCauseResolves) {
    Editor editor(defaultScene());
    UiState ui;
    reportProblems(ui, editor.setField({0, 0}, "radius", -1.0));
    reportProblems(ui, editor.setField({0, 0}, "radius", -2.0));
    reportProblems(ui, editor.setJsonValue("render.aa", 99));
    updateProblems(ui, editor);
    std::vector<const Message*> open = openErrors(ui);
    ASSERT_EQ(open.size(), 2u);
    EXPECT_NE(open[1]->text.find("got -2"), std::string::npos);
    ASSERT_TRUE(editor.remove({0, 0}).empty());
    updateProblems(ui, editor);
    open = openErrors(ui);
    ASSERT_EQ(open.size(), 1u);
    EXPECT_EQ(problemCause(open[0]->text)->jsonPath, "render.aa");
    ASSERT_TRUE(editor.setJsonValue("render.aa", 3).empty());
    updateProblems(ui, editor);
    EXPECT_TRUE(openErrors(ui).empty());
}

TEST(Problems, GoingToTheCauseSelectsItsNodeAndTab) {
    Editor editor(defaultScene());
    UiState ui;
    goToCause(editor, ui, *problemCause("root.children[1].children[0].children[0].half_extents: must be > 0"));
    EXPECT_EQ(editor.selection(), (NodePath{1, 0, 0}));
    EXPECT_EQ(ui.showTab, InspectorTab::Node);
    goToCause(editor, ui, *problemCause("environment.ground.cell_size: must be > 0"));
    EXPECT_EQ(ui.showTab, InspectorTab::Environment);
    EXPECT_FALSE(editor.canUndo());
}

}  // namespace
}  // namespace sdfwb::ui
