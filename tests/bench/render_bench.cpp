// Rendering benchmarks: CPU thread scaling on the default scene, GL shader
// compile time against scene size (cold Mesa cache), GL against CPU time, the
// cost of the ray tree (mirrors and glass) against the same scenes without it,
// the cost of the ground's footprint filter against the point pattern, and
// the cost of environment maps against the background colour, and of bump
// maps and textures against the same materials without them, and what
// distance-only evaluation saves on glass and bump scenes.
// Run: build/tests/bench/render_bench  (sets MESA_SHADER_CACHE_DISABLE=true itself)

#include <cstdlib>

#include <benchmark/benchmark.h>

#include "cpu/cpu_renderer.h"
#include "gl/gl_renderer.h"
#include "glcontext/osmesa_context.h"
#include "program/compile_scene.h"
#include "scene/scene_json.h"
#include "support/source_tree.h"

namespace sdfwb {
namespace {

scene::Scene defaultScene() { return scene::loadSceneFile(sdfwb::test::sourceDir() + "/scenes/default.json"); }

// A union of `count` translated spheres: about 3 * count instructions.
scene::Scene sphereCloud(int count) {
    scene::Scene s;
    for (int i = 0; i < count; ++i) {
        scene::Node translate = scene::Node::make(scene::NodeKind::Translate);
        translate.set("offset", glm::dvec3(i % 10, (i / 10) % 10, i / 100));
        scene::Node sphere = scene::Node::make(scene::NodeKind::Sphere);
        sphere.set("radius", 0.3);
        translate.children.push_back(sphere);
        s.root.children.push_back(translate);
    }
    return s;
}

void BM_CpuDefault1280x720(benchmark::State& state) {
    program::Program p = program::compileScene(defaultScene(), {.width = 1280, .height = 720, .aa = 2});
    for (auto _ : state) {
        benchmark::DoNotOptimize(cpu::renderCpu(p, {.threads = static_cast<int>(state.range(0))}));
    }
}
BENCHMARK(BM_CpuDefault1280x720)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

glcontext::OsMesaContext& context() {
    static auto c = glcontext::OsMesaContext::create();
    return *c;
}

// Cold compile: a fresh renderer per iteration and Mesa's disk cache off; the
// structure differs per iteration (one extra node) so no cache can help.
void BM_GlCompile(benchmark::State& state) {
    int nodes = static_cast<int>(state.range(0));
    int variant = 0;
    for (auto _ : state) {
        program::Program p = program::compileScene(sphereCloud(nodes / 2 + (variant++ % 2)));
        gl::GlRenderer renderer(context().gl());
        renderer.prepare(p);
        state.SetIterationTime(renderer.counters().lastCompileSeconds);
    }
}
BENCHMARK(BM_GlCompile)->Arg(10)->Arg(100)->Arg(1000)->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(2);

void BM_GlDefault1280x720(benchmark::State& state) {
    program::Program p = program::compileScene(defaultScene(), {.width = 1280, .height = 720, .aa = 2});
    gl::GlRenderer renderer(context().gl());
    renderer.prepare(p);
    for (auto _ : state) {
        benchmark::DoNotOptimize(renderer.render(p));
    }
}
BENCHMARK(BM_GlDefault1280x720)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

// Renders `p` once per benchmark iteration: CPU with 2 threads, or GL (the
// program built before the timed loop).
void renderEachIteration(benchmark::State& state, const program::Program& p, bool gl) {
    if (!gl) {
        for (auto _ : state) benchmark::DoNotOptimize(cpu::renderCpu(p, {.threads = 2}));
        return;
    }
    gl::GlRenderer renderer(context().gl());
    renderer.prepare(p);
    for (auto _ : state) benchmark::DoNotOptimize(renderer.render(p));
}

// What mirrors and glass cost: a scene with its ray tree (range 1) and the
// same scene with max_depth 0 (range 0: no tree compiled, primary rays only),
// 480x270 AA 1, CPU (2 threads) and GL, in one run.
void rayTreeCost(benchmark::State& state, const char* file, bool gl) {
    scene::Scene s = scene::loadSceneFile(sdfwb::test::sourceDir() + "/scenes/" + file);
    if (state.range(0) == 0) s.render.maxDepth = 0;
    program::Program p = program::compileScene(s, {.width = 480, .height = 270, .aa = 1});
    renderEachIteration(state, p, gl);
}
BENCHMARK_CAPTURE(rayTreeCost, mirrors_cpu, "tutorial/08_mirrors.json", false)
    ->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);
BENCHMARK_CAPTURE(rayTreeCost, mirrors_gl, "tutorial/08_mirrors.json", true)
    ->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);
BENCHMARK_CAPTURE(rayTreeCost, glass_cpu, "tutorial/09_glass.json", false)
    ->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);
BENCHMARK_CAPTURE(rayTreeCost, glass_gl, "tutorial/09_glass.json", true)
    ->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);
BENCHMARK_CAPTURE(rayTreeCost, showcase_cpu, "showcase/glass_and_chrome.json", false)
    ->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);
BENCHMARK_CAPTURE(rayTreeCost, showcase_gl, "showcase/glass_and_chrome.json", true)
    ->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);
BENCHMARK_CAPTURE(rayTreeCost, improved_shadows_cpu, "hard/improved_shadow_through_glass.json", false)
    ->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);
BENCHMARK_CAPTURE(rayTreeCost, improved_shadows_gl, "hard/improved_shadow_through_glass.json", true)
    ->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

// What the ground's footprint filter costs: scenes/default.json at 480x270
// AA 1 as compiled (range 1) and with the ground's footprint per distance set
// to 0 (range 0: every sample takes the point pattern), CPU (2 threads) and GL.
void groundFilterCost(benchmark::State& state, bool gl) {
    program::Program p = program::compileScene(defaultScene(), {.width = 480, .height = 270, .aa = 1});
    if (state.range(0) == 0) {
        for (const program::Instruction& in : p.code) {
            if (in.op == program::Opcode::Ground) p.params[static_cast<size_t>(in.param)].z = 0.0;
        }
    }
    renderEachIteration(state, p, gl);
}
BENCHMARK_CAPTURE(groundFilterCost, cpu, false)
    ->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);
BENCHMARK_CAPTURE(groundFilterCost, gl, true)
    ->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);

// What an environment map costs: the tutorial scenes with their map (range 1)
// and with the background colour instead (range 0: no sampler compiled),
// 480x270 AA 1, CPU (2 threads) and GL, in one run.
void environmentMapCost(benchmark::State& state, const char* file, bool gl) {
    scene::Scene s = scene::loadSceneFile(sdfwb::test::sourceDir() + "/scenes/" + file);
    if (state.range(0) == 0) s.environment.map = scene::EnvironmentMapKind::Color;
    program::Program p = program::compileScene(s, {.width = 480, .height = 270, .aa = 1});
    renderEachIteration(state, p, gl);
}
BENCHMARK_CAPTURE(environmentMapCost, equirect_cpu, "tutorial/11_environment_map.json", false)
    ->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);
BENCHMARK_CAPTURE(environmentMapCost, equirect_gl, "tutorial/11_environment_map.json", true)
    ->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);
BENCHMARK_CAPTURE(environmentMapCost, box_cpu, "tutorial/12_box_map.json", false)
    ->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);
BENCHMARK_CAPTURE(environmentMapCost, box_gl, "tutorial/12_box_map.json", true)
    ->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);

// What a material effect costs: a tutorial scene as it is (range 1) and with
// the effect taken off every material (range 0: none of its instructions
// compiled), 480x270 AA 1, CPU (2 threads) and GL, in one run.
void materialEffectCost(benchmark::State& state, const char* file, void (*takeOff)(scene::Material&), bool gl) {
    scene::Scene s = scene::loadSceneFile(sdfwb::test::sourceDir() + "/scenes/" + file);
    if (state.range(0) == 0) {
        for (scene::Material& m : s.materials) takeOff(m);
    }
    program::Program p = program::compileScene(s, {.width = 480, .height = 270, .aa = 1});
    renderEachIteration(state, p, gl);
}
void noBump(scene::Material& m) { m.bump = scene::BumpPattern::None; }
void noTexture(scene::Material& m) { m.texture = scene::TexturePattern::None; }

// tutorial 13: three bumped materials
BENCHMARK_CAPTURE(materialEffectCost, bump_cpu, "tutorial/13_bump_map.json", noBump, false)
    ->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);
BENCHMARK_CAPTURE(materialEffectCost, bump_gl, "tutorial/13_bump_map.json", noBump, true)
    ->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);
// tutorial 14: four image-textured primitives and a wall (whose image bump
// map stays on: its material phase takes five samples either way)
BENCHMARK_CAPTURE(materialEffectCost, image_texture_cpu, "tutorial/14_image_textures.json", noTexture, false)
    ->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);
BENCHMARK_CAPTURE(materialEffectCost, image_texture_gl, "tutorial/14_image_textures.json", noTexture, true)
    ->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);
// tutorial 10: checker, noise and stripes
BENCHMARK_CAPTURE(materialEffectCost, procedural_texture_cpu, "tutorial/10_procedural_textures.json", noTexture,
                  false)
    ->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);
BENCHMARK_CAPTURE(materialEffectCost, procedural_texture_gl, "tutorial/10_procedural_textures.json", noTexture,
                  true)
    ->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);

// What distance-only evaluation saves where some phases read a material
// field (cpu/interpreter.inl, Program::materialReads): the CPU backend with
// it (range 1) and carrying materials through every evaluation (range 0), on
// scenes with glass (shadows and the march's first sample read the
// transparency) and bump maps (the normal reads the height), 480x270 AA 1.
void distanceOnlyGain(benchmark::State& state, const char* file) {
    scene::Scene s = scene::loadSceneFile(sdfwb::test::sourceDir() + "/scenes/" + file);
    program::Program p = program::compileScene(s, {.width = 480, .height = 270, .aa = 1});
    p.distanceOnlyEvaluation = state.range(0) != 0;
    renderEachIteration(state, p, false);
}
BENCHMARK_CAPTURE(distanceOnlyGain, glass, "tutorial/09_glass.json")
    ->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);
BENCHMARK_CAPTURE(distanceOnlyGain, glass_and_chrome, "showcase/glass_and_chrome.json")
    ->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);
BENCHMARK_CAPTURE(distanceOnlyGain, bump, "tutorial/13_bump_map.json")
    ->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);
BENCHMARK_CAPTURE(distanceOnlyGain, textured_still_life, "showcase/textured_still_life.json")
    ->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);

}  // namespace
}  // namespace sdfwb

int main(int argc, char** argv) {
    setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
