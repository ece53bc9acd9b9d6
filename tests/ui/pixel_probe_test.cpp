// The pixel readout off the UI thread (issue 13): a request returns at once,
// its reading is the shared CPU pick of that pixel, a scene state is compiled
// once for every pixel of it, and a newer request supersedes older ones.

#include <gtest/gtest.h>

#include "support/source_tree.h"

#include "scene/scene_json.h"
#include "ui/pixel_probe.h"
#include "ui/view_picking.h"

namespace sdfwb::ui {
namespace {

scene::Scene defaultScene() { return scene::loadSceneFile(sdfwb::test::sourceDir() + "/scenes/default.json"); }

constexpr int kWidth = 480, kHeight = 270;

TEST(PixelProbe, TheReadingIsThePickOfThatPixel) {
    scene::Scene scene = defaultScene();
    PixelProbe probe;
    EXPECT_EQ(probe.latest(), std::nullopt);
    glm::dvec2 ball = *projectToView(scene, glm::dvec3(-0.9, 0.8, 0), kWidth, kHeight);
    probe.request(scene, 7, kWidth, kHeight, ball.x, ball.y);
    probe.wait();
    ASSERT_FALSE(probe.pending());
    std::optional<PixelReading> r = probe.latest();
    ASSERT_TRUE(r);
    EXPECT_EQ(r->revision, 7u);
    EXPECT_EQ(r->x, ball.x);
    cpu::PickResult direct = pickView(scene, kWidth, kHeight, ball.x, ball.y);
    EXPECT_TRUE(r->pick.hit);
    EXPECT_EQ(r->pick.node, (std::optional<std::vector<int>>(std::vector<int>{0, 0})));
    EXPECT_EQ(r->pick.steps, direct.steps);
    EXPECT_EQ(r->pick.distance, direct.distance);
    EXPECT_EQ(readoutText(r->pick), readoutText(direct));
    EXPECT_NE(readoutText(r->pick).find("root.children[0].children[0]"), std::string::npos) << readoutText(r->pick);
}

TEST(PixelProbe, OneCompilePerSceneStateAndTheNewestRequestWins) {
    scene::Scene scene = defaultScene();
    PixelProbe probe;
    for (int i = 0; i < 40; ++i) probe.request(scene, 1, kWidth, kHeight, 10.0 + i, 200.0);
    probe.wait();
    EXPECT_EQ(probe.programs()->compiles(), 1);
    EXPECT_EQ(probe.latest()->x, 49.0);  // the last one asked, whatever ran before it
    EXPECT_EQ(probe.latest()->pick.steps, pickView(scene, kWidth, kHeight, 49.0, 200.0).steps);

    probe.request(scene, 1, kWidth, kHeight, 49.0, 200.0);  // the same again: nothing to do
    EXPECT_FALSE(probe.pending());

    // a new state (the ball hidden) compiles again, and what lies behind the ball is read
    glm::dvec2 ball = *projectToView(scene, glm::dvec3(-0.9, 0.8, 0), kWidth, kHeight);
    scene.root.children[0].children[0].hidden = true;
    probe.request(scene, 2, kWidth, kHeight, ball.x, ball.y);
    probe.wait();
    EXPECT_EQ(probe.programs()->compiles(), 2);
    EXPECT_EQ(probe.latest()->revision, 2u);
    EXPECT_NE(probe.latest()->pick.node, (std::optional<std::vector<int>>(std::vector<int>{0, 0})));
}

TEST(PixelProbe, TwoProbesOfOneViewShareTheProgram) {
    scene::Scene scene = defaultScene();
    PixelProbe hover;
    PixelProbe click(hover.programs());
    hover.request(scene, 3, kWidth, kHeight, 100, 100);
    hover.wait();
    click.request(scene, 3, kWidth, kHeight, 120, 150);
    click.wait();
    EXPECT_EQ(hover.programs()->compiles(), 1);
    EXPECT_EQ(click.latest()->pick.steps, pickView(scene, kWidth, kHeight, 120, 150).steps);
}

}  // namespace
}  // namespace sdfwb::ui
