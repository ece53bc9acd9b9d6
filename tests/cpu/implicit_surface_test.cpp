// Where |F| / |grad F| overestimates the distance, a march step overshoots
// the surface. Into a solid: the march backs out onto the surface (a hit
// left inside started its shadow rays inside, and an implicit torus showed a
// black crescent in its hole). Over a sheet: sheet steps are capped at the
// sheet's thickness, so the live march covers what tiny steps cover (the
// Moebius strip's fold showed stripes of holes).

#include <gtest/gtest.h>

#include <vector>

#include "cpu/cpu_renderer.h"
#include "program/compile_scene.h"
#include "scene/scene_json.h"
#include "support/source_tree.h"

namespace sdfwb {
namespace {

std::vector<float> coverage(scene::Scene s) {
    s.render.width = 240;
    s.render.height = 135;
    s.render.aa = 1;
    s.render.shadows = scene::ShadowMode::None;
    s.render.aoSamples = 0;
    // a tenth of a pixel: tiny steps must stay above the hit epsilon
    s.render.epsilon = 0.1;
    return cpu::renderCpu(program::compileScene(s)).frame.coverage;
}

TEST(ImplicitSheet, CoversWhatTinyStepsCover) {
    scene::Scene live = scene::loadSceneFile(sdfwb::test::sourceDir() + "/scenes/hard/moebius_sheet.json");
    ASSERT_GT(live.root.real("sheet_thickness"), 0);
    scene::Scene tiny = live;
    tiny.root.set("max_step", 0.004);
    tiny.render.maxSteps = 8192;
    std::vector<float> a = coverage(live), b = coverage(tiny);
    size_t hits = 0, holes = 0, extra = 0;
    for (size_t i = 0; i < a.size(); ++i) {
        hits += b[i] > 0.5f;
        holes += b[i] > 0.5f && a[i] < 0.5f;
        extra += b[i] < 0.5f && a[i] > 0.5f;
    }
    ASSERT_GT(hits, a.size() / 4);
    // silhouette pixels may differ; the stripes were hundreds of pixels
    EXPECT_LE(holes, hits / 1000) << holes << " holes of " << hits << " hits";
    EXPECT_LE(extra, hits / 1000) << extra << " extra hits";
}

TEST(ImplicitSolid, HitsLieOnTheSurfaceAfterAnOvershoot) {
    // the same torus, exact and as its implicit quartic, seen into its hole,
    // where the bound overshoots by up to 12 %
    scene::Scene exact;
    exact.camera.target = glm::dvec3(0.0);
    exact.camera.azimuth = 15;
    exact.camera.elevation = 32;
    exact.camera.distance = 3.2;
    exact.environment.ground.enabled = false;
    exact.render.width = 160;
    exact.render.height = 90;
    exact.render.aa = 1;
    exact.render.epsilonMode = scene::EpsilonMode::Absolute;
    exact.render.epsilon = 1e-4;
    scene::Node torus = scene::Node::make(scene::NodeKind::Torus);
    torus.set("major_radius", 1.0);
    torus.set("minor_radius", 0.4);
    exact.root = torus;
    scene::Scene implicit = exact;
    implicit.root = scene::Node::make(scene::NodeKind::Polynomial);
    implicit.root.set("formula", std::string("(x^2 + y^2 + z^2 + 0.84)^2 - 4*(x^2 + z^2)"));
    implicit.root.set("bounds_min", glm::dvec3(-1.5, -0.5, -1.5));
    implicit.root.set("bounds_max", glm::dvec3(1.5, 0.5, 1.5));
    image::Frame a = cpu::renderCpu(program::compileScene(exact)).frame;
    image::Frame b = cpu::renderCpu(program::compileScene(implicit)).frame;
    size_t both = 0;
    double worst = 0;
    for (size_t i = 0; i < a.depth.size(); ++i) {
        if (a.coverage[i] < 1 || b.coverage[i] < 1) continue;
        ++both;
        worst = std::max(worst, std::abs(double(a.depth[i]) - double(b.depth[i])));
    }
    ASSERT_GT(both, a.depth.size() / 10);
    // a hit left inside was 0.015 deep
    EXPECT_LT(worst, 2e-3);
}

}  // namespace
}  // namespace sdfwb
