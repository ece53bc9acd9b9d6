// GUI smoke test: runs the real application under Xvfb with scripts and
// checks what they produced. One opens the default scene, changes a
// parameter, switches backend, undoes and saves: screenshots are not blank,
// the edit changed the viewport, undo restored it, the saved scene is the
// expected one. One implicitizes in the Polynomial window and adds the
// surface: it shows, and the saved node has the equation and sampled bounds.
// Skipped when no X server can start, unless SDFWB_REQUIRE_GL=1.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "image/image_io.h"
#include "scene/scene_json.h"
#include "ui/node_path.h"

namespace sdfwb::ui {
namespace {

namespace fs = std::filesystem;

bool glRequired() {
    const char* value = std::getenv("SDFWB_REQUIRE_GL");
    return value && std::string(value) == "1";
}

std::string readAll(const fs::path& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

// Where the viewport shows the scene at 1280x800 (left of the 390-pixel side
// column), below the statistics overlay and above the status bar.
struct Crop {
    int x0, y0, x1, y1;
};
Crop viewportCrop(const image::Image& shot) {
    return {shot.width * 5 / 100, shot.height * 30 / 100, shot.width * 65 / 100, shot.height * 90 / 100};
}

// Mean absolute difference in levels of 255, over the crop.
double meanDifference(const image::Image& a, const image::Image& b) {
    Crop c = viewportCrop(a);
    double sum = 0;
    size_t count = 0;
    for (int y = c.y0; y < c.y1; ++y) {
        for (int x = c.x0; x < c.x1; ++x) {
            for (size_t ch = 0; ch < 3; ++ch) {
                size_t i = (static_cast<size_t>(y) * static_cast<size_t>(a.width) + static_cast<size_t>(x)) * 3 + ch;
                sum += std::abs(a.rgb[i] - b.rgb[i]) * 255.0;
                ++count;
            }
        }
    }
    return sum / static_cast<double>(count);
}

// Standard deviation of the crop's luminance: near zero for a blank image.
double contrast(const image::Image& shot) {
    Crop c = viewportCrop(shot);
    double sum = 0, squares = 0;
    size_t count = 0;
    for (int y = c.y0; y < c.y1; ++y) {
        for (int x = c.x0; x < c.x1; ++x) {
            size_t i = (static_cast<size_t>(y) * static_cast<size_t>(shot.width) + static_cast<size_t>(x)) * 3;
            double v = (shot.rgb[i] + shot.rgb[i + 1] + shot.rgb[i + 2]) / 3.0;
            sum += v;
            squares += v * v;
            ++count;
        }
    }
    double mean = sum / static_cast<double>(count);
    return std::sqrt(std::max(0.0, squares / static_cast<double>(count) - mean * mean));
}

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
// test output, with its own XDG folders; returns that folder.
fs::path runScript(const std::string& name, const char* script) {
    fs::path dir = fs::path(SDFWB_TEST_OUTPUT_DIR) / name;
    fs::remove_all(dir);
    fs::create_directories(dir / "config");
    fs::create_directories(dir / "state");
    std::ofstream(dir / "script.txt") << script;
    std::string command = "cd '" + dir.string() + "' && env XDG_CONFIG_HOME='" + (dir / "config").string() +
                          "' XDG_STATE_HOME='" + (dir / "state").string() + "' xvfb-run -a -s '-screen 0 1280x800x24' '" +
                          SDFWB_WORKBENCH + "' gui --script script.txt > run.log 2>&1";
    int status = std::system(command.c_str());
    EXPECT_EQ(status, 0) << "the workbench failed:\n" << readAll(dir / "run.log");
    return dir;
}

class GuiSmokeTest : public ::testing::Test {
protected:
    void SetUp() override {
        if (std::system("xvfb-run -a true > /dev/null 2>&1") != 0) {
            if (glRequired()) GTEST_FAIL() << "no X server could start (xvfb-run -a true failed), and SDFWB_REQUIRE_GL=1";
            GTEST_SKIP() << "no X server could start (xvfb-run -a true failed)";
        }
    }
};

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
        EXPECT_GT(contrast(*shot), 0.02) << "a screenshot's viewport is blank";
    }
    double editChange = meanDifference(before, edited);
    double backendChange = meanDifference(edited, cpuEdited);
    double undoChange = meanDifference(before, undone);
    std::cout << "viewport mean difference (levels): edit " << editChange << ", GL vs CPU " << backendChange
              << ", before vs after undo " << undoChange << "\n";
    EXPECT_GT(editChange, 2.0) << "the edit did not change the viewport";
    EXPECT_LT(backendChange, 1.0) << "the CPU backend's view differs from the GLSL backend's";
    EXPECT_LT(undoChange, 0.05) << "undo did not restore the viewport";

    scene::Scene expected = scene::loadSceneFile(fs::path(SDFWB_SOURCE_DIR) / "scenes/default.json");
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
    double change = meanDifference(image::readImage(dir / "before.png"), image::readImage(dir / "added.png"));
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
