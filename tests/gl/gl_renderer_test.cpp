// The GLSL backend: shaders specialised to the scene, compiled once per
// structure (parameter edits compile nothing), golden map() text, and the
// same frame layout as the CPU backend.

#include <algorithm>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "cpu/cpu_renderer.h"
#include "gl/gl_renderer.h"
#include "gl/shader_generator.h"
#include "gl_test_support.h"
#include "image/compare.h"
#include "program/compile_scene.h"
#include "scene/scene_json.h"
#include "sdf/glsl_sources.h"
#include "support/source_tree.h"

namespace sdfwb {
namespace {

using scene::Node;
using scene::NodeKind;

scene::Scene defaultScene() { return scene::loadSceneFile(sdfwb::test::sourceDir() + "/scenes/default.json"); }

// The generated map() function alone: the part of the shader the generator writes.
std::string mapFunction(const std::string& shader) {
    size_t begin = shader.find("Sample map(vec3 p)");
    size_t end = shader.find("\n}\n", begin);
    return shader.substr(begin, end + 3 - begin);
}

TEST(ShaderGenerator, MapFunctionMatchesGoldenText) {
    for (const char* name : {"scenes/default", "tests/data/golden/operators"}) {
        SCOPED_TRACE(name);
        std::string scenePath = sdfwb::test::sourceDir() + "/" + name + ".json";
        program::Program p = program::compileScene(scene::loadSceneFile(scenePath));
        std::string actual = mapFunction(gl::generateFragmentShader(p));
        std::string goldenName = std::filesystem::path(name).filename().string();
        std::filesystem::path golden = sdfwb::test::sourceDir() + "/tests/data/golden/" + goldenName + ".map.glsl";
        std::filesystem::create_directories(sdfwb::test::outputDir());
        std::ofstream(std::filesystem::path(sdfwb::test::outputDir()) / (goldenName + ".map.glsl")) << actual;
        std::ifstream in(golden);
        ASSERT_TRUE(in) << "missing golden " << golden << "; candidate in " << sdfwb::test::outputDir();
        std::stringstream expected;
        expected << in.rdbuf();
        EXPECT_EQ(actual, expected.str());
    }
}

TEST(ShaderGenerator, ContainsOnlyTheInstructionsTheSceneUses) {
    scene::Scene s;
    s.root = Node::make(NodeKind::Sphere);
    std::string map = mapFunction(gl::generateFragmentShader(program::compileScene(s)));
    EXPECT_NE(map.find("instSphere"), std::string::npos);
    EXPECT_EQ(map.find("instBox"), std::string::npos);
    EXPECT_EQ(map.find("instSmoothUnion"), std::string::npos);
}

TEST(ShaderGenerator, EveryOpcodeHasItsSharedFunction) {
    for (const program::OpcodeInfo& info : program::kOpcodes) {
        std::string signature = std::string(" ") + std::string(info.function) + "(";
        std::string shared = std::string(sdf::glslLibrary()) + std::string(sdf::glslTextureLookup());
        EXPECT_NE(shared.find(signature), std::string::npos) << info.name;
    }
}

TEST(ShaderGenerator, WorstCaseLoopCountOfTheLargestValidSettingsStaysUnderTheLimiter) {
    scene::Scene s = scene::parseScene(R"({"format": "sdf-workbench-scene", "version": 1,
        "render": {"max_steps": 8192, "shadow_steps": 4096, "ao_samples": 64},
        "lights": [{}, {}, {}, {}, {}, {}, {}, {}], "root": {"kind": "sphere"}})");
    EXPECT_LT(gl::worstCaseBackEdges(program::compileScene(s)), gl::kLoopLimiter);
}

class GlRendererTest : public test::GlTest {};

TEST_F(GlRendererTest, ParameterEditsCompileNothingStructuralEditsCompileOnce) {
    gl::GlRenderer renderer(gl());
    scene::Scene s = defaultScene();
    program::CompileOptions small{.width = 32, .height = 18, .aa = 1};
    renderer.render(program::compileScene(s, small));
    EXPECT_EQ(renderer.counters().compiles, 1);

    // parameter edits: a radius, a material colour, a light, the camera, AA
    s.root.children[0].children[0].set("radius", 0.5);
    s.materials[0].diffuse = {0.1, 0.9, 0.1};
    s.lights[0].softness = 4;
    s.camera.azimuth = 75;
    renderer.render(program::compileScene(s, small));
    renderer.render(program::compileScene(s, {.width = 40, .height = 20, .aa = 3}));
    EXPECT_EQ(renderer.counters().compiles, 1);
    EXPECT_EQ(renderer.counters().generations, 1);
    EXPECT_EQ(renderer.counters().cacheHits, 2);

    // structural edit: a new node
    s.root.children.push_back(Node::make(NodeKind::Torus));
    renderer.render(program::compileScene(s, small));
    EXPECT_EQ(renderer.counters().compiles, 2);
    // and back: the first program is still cached
    s.root.children.pop_back();
    renderer.render(program::compileScene(s, small));
    EXPECT_EQ(renderer.counters().compiles, 2);
}

TEST_F(GlRendererTest, FrameMatchesTheCpuBackendLayout) {
    program::Program p = program::compileScene(defaultScene(), {.width = 48, .height = 27, .aa = 2});
    gl::GlRenderer renderer(gl());
    render::RenderOutcome glFrame = renderer.render(p, {.tileSize = 16});
    render::RenderOutcome cpuFrame = cpu::renderCpu(p);
    ASSERT_EQ(glFrame.frame.color.width, 48);
    ASSERT_EQ(glFrame.frame.color.height, 27);
    EXPECT_EQ(glFrame.frame.coverage, cpuFrame.frame.coverage);
    EXPECT_EQ(glFrame.frame.steps, cpuFrame.frame.steps);
    EXPECT_EQ(glFrame.frame.depth, cpuFrame.frame.depth);
    image::Comparison c = image::compareImages(glFrame.frame.color, cpuFrame.frame.color);
    EXPECT_LE(c.maxAbs, 1.0);
}

TEST_F(GlRendererTest, CancelBetweenDrawsReportsCancelled) {
    program::Program p = program::compileScene(defaultScene(), {.width = 64, .height = 64, .aa = 2});
    gl::GlRenderer renderer(gl());
    std::atomic<bool> cancel{false};
    render::RenderOutcome outcome =
        renderer.render(p, {.tileSize = 16, .cancel = &cancel, .progress = [&](int done, int) { cancel = done >= 2; }});
    EXPECT_TRUE(outcome.cancelled);
}

}  // namespace
}  // namespace sdfwb
