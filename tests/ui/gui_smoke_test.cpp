// GUI smoke test: runs the real application under Xvfb with scripts and
// checks what they produced. One opens the default scene, changes a
// parameter, switches backend, undoes and saves: screenshots are not blank,
// the edit changed the viewport, undo restored it, the saved scene is the
// expected one. One implicitizes in the Polynomial window and adds the
// surface: it shows, and the saved node has the equation and sampled bounds.
// Skipped when no X server can start, unless SDFWB_REQUIRE_GL=1.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "image/image_io.h"
#include "scene/scene_json.h"
#include "support/source_tree.h"
#include "ui/gui_run.h"
#include "ui/node_path.h"

namespace sdfwb::ui {
namespace {

namespace fs = std::filesystem;

constexpr const char* kScript = R"(# GUI smoke test: edit, switch backend, undo, save
# AA 1 keeps the CPU backend's renders short on a shared CI machine
set render.aa 1
# selected first: the selection outline is in every screenshot compared
select root.children[0].children[0]
wait idle
screenshot before.png
set radius 0.4
screenshot edited.png
backend cpu
screenshot cpu-edited.png
undo
backend gl
screenshot undone.png
set material blue
save saved.json
quit
)";

// Runs the workbench under Xvfb on `script` in a fresh folder `name` of the
// test output; returns that folder.
fs::path runScript(const std::string& name, const char* script) {
    fs::path dir = test::makeGuiFolder(name, script);
    test::runGuiScript(dir);
    return dir;
}

using GuiSmokeTest = test::GuiTest;

TEST_F(GuiSmokeTest, ScriptedEditSwitchUndoAndSave) {
    fs::path dir = runScript("gui_smoke", kScript);
    ASSERT_FALSE(HasFailure());

    image::Image before = image::readImage(dir / "before.png");
    image::Image edited = image::readImage(dir / "edited.png");
    image::Image cpuEdited = image::readImage(dir / "cpu-edited.png");
    image::Image undone = image::readImage(dir / "undone.png");
    ASSERT_EQ(before.width, 1280);
    ASSERT_EQ(before.height, 800);
    for (const image::Image* shot : {&before, &edited, &cpuEdited, &undone}) {
        EXPECT_GT(test::contrast(*shot), 0.02) << "a screenshot's viewport is blank";
    }
    double editChange = test::meanDifference(before, edited);
    double backendChange = test::meanDifference(edited, cpuEdited);
    double undoChange = test::meanDifference(before, undone);
    std::cout << "viewport mean difference (levels): edit " << editChange << ", GL vs CPU " << backendChange
              << ", before vs after undo " << undoChange << "\n";
    EXPECT_GT(editChange, 2.0) << "the edit did not change the viewport";
    EXPECT_LT(backendChange, 1.0) << "the CPU backend's view differs from the GLSL backend's";
    EXPECT_LT(undoChange, 0.05) << "undo did not restore the viewport";

    scene::Scene expected = scene::loadSceneFile(fs::path(sdfwb::test::sourceDir()) / "scenes/default.json");
    expected.render.aa = 1;
    findNode(expected.root, {0, 0})->set("material", std::string("blue"));
    EXPECT_EQ(scene::loadSceneFile(dir / "saved.json"), expected);
    EXPECT_FALSE(fs::exists(dir / "state/sdf-workbench/autosave.json")) << "a scripted run must not autosave";
}

constexpr const char* kPolynomialScript = R"(# the Polynomial window: implicitize, add the surface, save
set render.aa 1
wait idle
screenshot before.png
polynomial open
polynomial equations x = u*v; y = v; z = u^2
polynomial range u -0.8 0.8
polynomial run
polynomial add
polynomial close
wait idle
screenshot added.png
save saved.json
quit
)";

TEST_F(GuiSmokeTest, PolynomialWindowAddsTheImplicitSurface) {
    fs::path dir = runScript("gui_smoke_polynomial", kPolynomialScript);
    ASSERT_FALSE(HasFailure());
    double change = test::meanDifference(image::readImage(dir / "before.png"), image::readImage(dir / "added.png"));
    std::cout << "viewport mean difference after adding the Whitney umbrella (levels): " << change << "\n";
    EXPECT_GT(change, 1.0) << "the added surface does not show";
    scene::Scene saved = scene::loadSceneFile(dir / "saved.json");
    ASSERT_FALSE(saved.root.children.empty());
    const scene::Node& added = saved.root.children.back();
    EXPECT_EQ(added.kind, scene::NodeKind::Polynomial);
    EXPECT_EQ(added.text("formula"), "y^2*z - x^2");
    // u in [-0.8, 0.8] and v in [-1, 1]: x = u*v within 0.8, padded by 5 %
    EXPECT_NEAR(added.vec3("bounds_max").x, 0.88, 1e-9);
}

}  // namespace
}  // namespace sdfwb::ui
