// Selecting in the viewport (issue 13, item 6): a click selects the node the
// pixel shows, the ground and the sky clear the selection, and the outline
// covers the selected node's projection.

#include <gtest/gtest.h>

#include "scene/scene_json.h"
#include "support/source_tree.h"
#include "ui/script.h"
#include "ui/view_picking.h"

namespace sdfwb::ui {
namespace {

scene::Scene defaultScene() { return scene::loadSceneFile(sdfwb::test::sourceDir() + "/scenes/default.json"); }

TEST(ViewPicking, AClickSelectsTheNodeUnderThePixel) {
    Editor editor(defaultScene());
    const int w = 480, h = 270;
    glm::dvec2 ball = *projectToView(editor.scene(), glm::dvec3(-0.9, 0.8, 0), w, h);
    selectPicked(editor, pickView(editor.scene(), w, h, ball.x, ball.y));
    EXPECT_EQ(editor.selection(), (NodePath{0, 0}));
    glm::dvec2 crate = *projectToView(editor.scene(), glm::dvec3(1.1, 0.6, 0.2), w, h);
    selectPicked(editor, pickView(editor.scene(), w, h, crate.x, crate.y));
    EXPECT_EQ(editor.selection(), (NodePath{1, 0, 0}));
    selectPicked(editor, pickView(editor.scene(), w, h, w / 2.0, 2));  // the sky
    EXPECT_EQ(editor.selection(), std::nullopt);
    EXPECT_FALSE(editor.canUndo());  // selecting is not an edit
}

TEST(ViewPicking, TheOutlineCoversTheSelectedNode) {
    scene::Scene scene = defaultScene();
    const int w = 480, h = 270;
    std::optional<ImageRect> rect = outlineRect(scene, {0, 0}, w, h);
    ASSERT_TRUE(rect);
    glm::dvec2 centre = *projectToView(scene, glm::dvec3(-0.9, 0.8, 0), w, h);
    glm::dvec2 top = *projectToView(scene, glm::dvec3(-0.9, 1.6, 0), w, h);
    for (glm::dvec2 p : {centre, top}) {
        EXPECT_LE(rect->min.x, p.x);
        EXPECT_LE(rect->min.y, p.y);
        EXPECT_GE(rect->max.x, p.x);
        EXPECT_GE(rect->max.y, p.y);
    }
    EXPECT_LT(rect->max.x - rect->min.x, w / 2.0);
    scene.root.children.push_back(scene::Node::make(scene::NodeKind::Plane));
    EXPECT_EQ(outlineRect(scene, {2}, w, h), std::nullopt);  // unbounded
}

}  // namespace
}  // namespace sdfwb::ui
