// Mirrors and glass through the whole CPU pipeline (scene, compiler, kernel):
// a mirror floor shows k_ps M_PS times the background it reflects, and the
// ray tree changes nothing where no material reflects or transmits.

#include <gtest/gtest.h>

#include "cpu/cpu_renderer.h"
#include "program/compile_scene.h"
#include "scene/scene.h"
#include "scene/scene_json.h"
#include "support/source_tree.h"

namespace sdfwb {
namespace {

// Looking down at a floor that is only a mirror: no ambient light, no
// diffuse or specular, no lights; what it shows is M_PS times k_ps times the
// background its reflected rays escape to.
TEST(RayTreeRender, AMirrorFloorShowsTheBackgroundTimesKpsMps) {
    scene::Scene s;
    s.lights.clear();
    s.environment.ambient = glm::dvec3(0);
    s.environment.background = glm::dvec3(0.2, 0.4, 0.6);
    s.environment.ground.enabled = true;
    s.environment.ground.pattern = scene::GroundPattern::Plain;
    s.environment.ground.material = "mirror";
    scene::Material mirror;
    mirror.name = "mirror";
    mirror.ambient = mirror.diffuse = mirror.specular = glm::dvec3(0);
    mirror.reflectivity = 0.75;
    mirror.reflectionColor = glm::dvec3(1.0, 0.5, 0.25);
    s.materials.push_back(mirror);
    s.camera = {.target = {0, 0, 0}, .azimuth = 0, .elevation = 60, .distance = 3, .fov = 30};
    program::Program p = program::compileScene(s, {.width = 16, .height = 16, .aa = 1});
    ASSERT_TRUE(p.secondaryRays);
    for (render::Precision precision : {render::Precision::Float, render::Precision::Double}) {
        render::RenderOutcome outcome = cpu::renderCpu(p, {.precision = precision});
        const image::Image& c = outcome.frame.color;
        for (int i = 0; i < 16 * 16; ++i) {
            ASSERT_EQ(outcome.frame.coverage[static_cast<size_t>(i)], 1.0f);  // every pixel sees the floor
            EXPECT_NEAR(c.rgb[static_cast<size_t>(3 * i)], 0.75 * 1.0 * 0.2, 1e-6);
            EXPECT_NEAR(c.rgb[static_cast<size_t>(3 * i + 1)], 0.75 * 0.5 * 0.4, 1e-6);
            EXPECT_NEAR(c.rgb[static_cast<size_t>(3 * i + 2)], 0.75 * 0.25 * 0.6, 1e-6);
        }
    }
}

// A mirror whose field bounds the distance loosely (slope 0.3: a sphere's
// distance times 0.3) sends its reflected rays off its own surface, where
// the field reads less than the offset they start at: nothing but the
// reflected background may show on it, in float and in double.
TEST(RayTreeRender, AMirrorOnALooseBoundReflectsTheBackground) {
    scene::Scene s;
    s.lights.clear();
    s.environment.ambient = glm::dvec3(0);
    s.environment.background = glm::dvec3(0.2, 0.4, 0.6);
    s.environment.ground.enabled = false;
    scene::Material mirror;
    mirror.name = "mirror";
    mirror.ambient = mirror.diffuse = mirror.specular = glm::dvec3(0);
    mirror.reflectivity = 0.75;
    mirror.reflectionColor = glm::dvec3(1.0, 0.5, 0.25);
    s.materials.push_back(mirror);
    scene::Node ball = scene::Node::make(scene::NodeKind::Sdf);
    ball.set("formula", std::string("0.3 * (length(p) - 1)"));
    ball.set("material", std::string("mirror"));
    s.root.children.push_back(ball);
    s.render.epsilon = 1e-3;
    s.camera = {.target = {0, 0, 0}, .azimuth = 0, .elevation = 20, .distance = 4, .fov = 40};
    program::Program p = program::compileScene(s, {.width = 32, .height = 32, .aa = 1});
    ASSERT_TRUE(p.secondaryRays);
    const glm::dvec3 reflected = 0.75 * mirror.reflectionColor * s.environment.background;
    for (render::Precision precision : {render::Precision::Float, render::Precision::Double}) {
        render::RenderOutcome outcome = cpu::renderCpu(p, {.precision = precision});
        const image::Image& c = outcome.frame.color;
        int onMirror = 0;
        for (int i = 0; i < 32 * 32; ++i) {
            if (outcome.frame.coverage[static_cast<size_t>(i)] < 1.0f) continue;
            ++onMirror;
            for (int k = 0; k < 3; ++k) {
                EXPECT_NEAR(c.rgb[static_cast<size_t>(3 * i + k)], reflected[k], 1e-5) << "pixel " << i;
            }
        }
        EXPECT_GT(onMirror, 32 * 32 / 8);
    }
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
