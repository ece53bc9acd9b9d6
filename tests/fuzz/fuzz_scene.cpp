// Fuzz target: the scene loader and what a loaded scene reaches before its
// first pixel. Any bytes either load or fail with SceneError; a scene that
// loads saves and reloads to the same scene, compiles into a program (no
// exception: a loaded scene is valid), has its field evaluated at a few
// points in both precisions, and has its GLSL generated unless the size
// check refuses it, as the GL backend would, without needing a GL context.
// Rendering is left out: a valid scene may legitimately take long to render.

#include <cstdint>
#include <cstdlib>
#include <string_view>

#include <glm/glm.hpp>

#include "cpu/cpu_renderer.h"
#include "gl/program_size.h"
#include "gl/shader_generator.h"
#include "program/compile_scene.h"
#include "scene/scene_json.h"

namespace {

// The eye and points ahead of it, near and far, off the view axis too: march
// coordinates, where the eye is the origin.
void evaluateAroundTheView(const sdfwb::program::Program& program) {
    using sdfwb::render::Precision;
    const sdfwb::program::CameraParams& camera = program.camera;
    for (double t : {0.0, 0.5, 4.0, 60.0}) {
        for (double side : {0.0, 0.3}) {
            const glm::dvec3 point = t * (camera.forward + side * (camera.right + camera.up));
            sdfwb::cpu::evaluateDistance(program, point, Precision::Float);
            sdfwb::cpu::evaluateDistance(program, point, Precision::Double);
        }
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace sdfwb;
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    scene::Scene loaded;
    try {
        loaded = scene::parseScene(text);
    } catch (const scene::SceneError& error) {
        if (error.problems().empty()) std::abort();
        return 0;
    }
    if (scene::parseScene(scene::serializeScene(loaded)) != loaded) std::abort();
    // a small image: the settings that scale with it (the pixel epsilon, the
    // texture footprint) are computed, no grid is built
    const program::Program program = program::compileScene(loaded, {.width = 8, .height = 6, .aa = 1, .prune = false});
    evaluateAroundTheView(program);
    if (gl::shaderSizeProblem(program).empty()) gl::generateFragmentShader(program);
    return 0;
}
