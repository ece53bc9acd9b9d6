// Mirrors and glass through the whole CPU pipeline (scene, compiler, kernel):
// a mirror floor shows k_ps M_PS times the background it reflects, and the
// ray tree changes nothing where no material reflects or transmits.

#include <algorithm>

#include <gtest/gtest.h>

#include "cpu/cpu_renderer.h"
#include "program/compile_scene.h"
#include "scene/scene.h"
#include "scene/scene_json.h"
#include "support/source_tree.h"

namespace sdfwb {
namespace {

// A scene lit only by its background (no lights, no ambient light) with a
// material "mirror" that only reflects, k_ps = 0.75 and M_PS = (1, 0.5,
// 0.25): a mirror shows k_ps M_PS times the background its reflected rays
// escape to.
scene::Scene mirrorUnderTheSky() {
    scene::Scene s;
    s.lights.clear();
    s.environment.ambient = glm::dvec3(0);
    s.environment.background = glm::dvec3(0.2, 0.4, 0.6);
    scene::Material mirror;
    mirror.name = "mirror";
    mirror.ambient = mirror.diffuse = mirror.specular = glm::dvec3(0);
    mirror.reflectivity = 0.75;
    mirror.reflectionColor = glm::dvec3(1.0, 0.5, 0.25);
    s.materials.push_back(mirror);
    return s;
}

// Checks that every pixel that sees a surface shows the mirror's reflected
// background, in float and in double; returns how many pixels saw one (the
// fewer of the two renders').
int expectTheReflectedBackground(const scene::Scene& s, const program::Program& p) {
    const scene::Material& mirror = s.materials[0];
    const glm::dvec3 reflected = mirror.reflectivity * mirror.reflectionColor * s.environment.background;
    int fewest = p.width * p.height;
    for (render::Precision precision : {render::Precision::Float, render::Precision::Double}) {
        render::RenderOutcome outcome = cpu::renderCpu(p, {.precision = precision});
        const image::Image& c = outcome.frame.color;
        int surface = 0;
        for (int i = 0; i < p.width * p.height; ++i) {
            if (outcome.frame.coverage[static_cast<size_t>(i)] < 1.0f) continue;
            ++surface;
            for (int k = 0; k < 3; ++k) {
                EXPECT_NEAR(c.rgb[static_cast<size_t>(3 * i + k)], reflected[k], 1e-5) << "pixel " << i;
            }
        }
        fewest = std::min(fewest, surface);
    }
    return fewest;
}

// Looking down at a floor that is only a mirror: every pixel sees it.
TEST(RayTreeRender, AMirrorFloorShowsTheBackgroundTimesKpsMps) {
    scene::Scene s = mirrorUnderTheSky();
    s.environment.ground.enabled = true;
    s.environment.ground.pattern = scene::GroundPattern::Plain;
    s.environment.ground.material = "mirror";
    s.camera = {.target = {0, 0, 0}, .azimuth = 0, .elevation = 60, .distance = 3, .fov = 30};
    program::Program p = program::compileScene(s, {.width = 16, .height = 16, .aa = 1});
    ASSERT_TRUE(p.secondaryRays);
    EXPECT_EQ(expectTheReflectedBackground(s, p), 16 * 16);
}

// A mirror whose field bounds the distance loosely (slope 0.3: a sphere's
// distance times 0.3) sends its reflected rays off its own surface, where
// the field reads less than the offset they start at: nothing but the
// reflected background may show on it.
TEST(RayTreeRender, AMirrorOnALooseBoundReflectsTheBackground) {
    scene::Scene s = mirrorUnderTheSky();
    s.environment.ground.enabled = false;
    scene::Node ball = scene::Node::make(scene::NodeKind::Sdf);
    ball.set("formula", std::string("0.3 * (length(p) - 1)"));
    ball.set("material", std::string("mirror"));
    s.root.children.push_back(ball);
    s.render.epsilon = 1e-3;
    s.camera = {.target = {0, 0, 0}, .azimuth = 0, .elevation = 20, .distance = 4, .fov = 40};
    program::Program p = program::compileScene(s, {.width = 32, .height = 32, .aa = 1});
    ASSERT_TRUE(p.secondaryRays);
    EXPECT_GT(expectTheReflectedBackground(s, p), 32 * 32 / 8);
}

// With every k_ps = k_t = 0 the tree holds the primary ray alone, weight 1:
// the images are bit-identical to the tracer's without the tree.
TEST(RayTreeRender, OpaqueScenesRenderBitIdenticallyThroughTheTree) {
    for (const char* file : {"/scenes/default.json", "/scenes/tutorial/06_ambient_occlusion.json"}) {
        program::Program p = program::compileScene(scene::loadSceneFile(sdfwb::test::sourceDir() + file),
                                                   {.width = 64, .height = 36, .aa = 2});
        ASSERT_FALSE(p.secondaryRays) << file;
        program::Program tree = p;
        tree.secondaryRays = true;
        render::RenderOutcome without = cpu::renderCpu(p), with = cpu::renderCpu(tree);
        EXPECT_EQ(without.frame.color.rgb, with.frame.color.rgb) << file;
        EXPECT_EQ(without.frame.steps, with.frame.steps) << file;
        EXPECT_EQ(without.frame.evaluations, with.frame.evaluations) << file;
        EXPECT_EQ(without.frame.coverage, with.frame.coverage) << file;
        EXPECT_EQ(without.frame.depth, with.frame.depth) << file;
    }
}

TEST(RayTreeRender, OnlyReflectingOrTransmittingMaterialsWithADepthMakeATree) {
    scene::Scene s;
    scene::Material m;
    m.name = "m";
    s.materials.push_back(m);
    EXPECT_FALSE(program::compileScene(s).secondaryRays);
    s.materials[0].transparency = 0.5;
    EXPECT_TRUE(program::compileScene(s).secondaryRays);
    EXPECT_NE(program::compileScene(s).structureKey(), program::compileScene(scene::Scene{}).structureKey());
    s.render.maxDepth = 0;
    EXPECT_FALSE(program::compileScene(s).secondaryRays);
}

// Once a scene has its tree, the new fields are parameters: editing them
// (but for turning the last mirror or glass off) keeps the structure, so the
// GL backend builds no new shader.
TEST(RayTreeRender, MirrorAndGlassEditsAreParameterEdits) {
    scene::Scene s;
    scene::Material m;
    m.name = "m";
    m.reflectivity = 0.25;
    s.materials.push_back(m);
    std::uint64_t key = program::compileScene(s).structureKey();
    scene::Material& e = s.materials[0];
    e.reflectivity = 0.9;
    e.reflectionColor = {0.2, 0.4, 0.6};
    e.transparency = 0.7;
    e.transmissionColor = {0.9, 0.8, 0.7};
    e.ior = 1.33;
    e.fresnel = true;
    s.render.maxDepth = 6;
    s.render.rayWeightCutoff = 0.1;
    program::Program edited = program::compileScene(s);
    EXPECT_TRUE(edited.secondaryRays);
    EXPECT_EQ(edited.structureKey(), key);
    e.reflectivity = e.transparency = 0;
    EXPECT_NE(program::compileScene(s).structureKey(), key);  // no tree left to compile
}

}  // namespace
}  // namespace sdfwb
