#include "cpu/pick.h"

#include <algorithm>
#include <cmath>

#include "cpu/cpu_renderer.h"
#include "cpu/interpreter.h"
#include "program/compile_scene.h"
#include "scene/camera_frame.h"
#include "scene/visibility.h"
#include "sdf/shared.h"

namespace sdfwb::cpu {
namespace {

using program::Instruction;
using program::Opcode;

constexpr int kNothing = -1;  // an empty boolean: no primitive
constexpr int kGround = -2;

bool isPrimitive(const scene::Node& node) {
    return scene::kindSpec(node.kind).category == scene::NodeCategory::Primitive;
}

// The primitives the compiler draws, in its order (hidden ones compile to nothing).
void collectPrimitives(const scene::Node& node, const scene::Visibility& visibility, std::vector<int>& path,
                       std::vector<std::vector<int>>& out) {
    if (!visibility.draws(node)) return;
    if (isPrimitive(node)) out.push_back(path);
    for (size_t i = 0; i < node.children.size(); ++i) {
        path.push_back(static_cast<int>(i));
        collectPrimitives(node.children[i], visibility, path, out);
        path.pop_back();
    }
}

// Which operand's primitive a boolean's result at this point comes from:
// true for `a`. A smooth blend counts as its hard counterpart.
bool resultFromFirst(Opcode op, float a, float b) {
    switch (op) {
    case Opcode::Union:
    case Opcode::SmoothUnion: return a <= b;
    case Opcode::Intersection:
    case Opcode::SmoothIntersection: return a >= b;
    case Opcode::Difference:
    case Opcode::SmoothDifference: return a >= -b;  // max(a, -b): the cutter where it cuts
    default: return true;
    }
}

// The deciding primitive's number (or kGround, kNothing) at a march point:
// each instruction runs alone through the interpreter on the same registers,
// so every intermediate sample is the one the full program computes.
int decidingShape(const program::Program& program, const f32::Kernel& kernel, f32::vec3 point) {
    f32::Scratch scratch(program);
    program::Program single;
    single.code.resize(1);
    std::vector<int> source(scratch.samples.size(), kNothing);
    int nextShape = 0;
    for (const Instruction& in : program.code) {
        program::OpClass opClass = program::opcodeInfo(in.op).opClass;
        bool combine = program::isCombineClass(opClass);
        float a = combine ? scratch.samples[static_cast<size_t>(in.a)].d : 0.0f;
        float b = combine ? scratch.samples[static_cast<size_t>(in.b)].d : 0.0f;
        single.code[0] = in;
        single.result = opClass == program::OpClass::Point ? 0 : in.dst;  // mapProgram reads a sample register
        f32::mapProgram(single, kernel.params.data(), scratch, point);
        auto dst = static_cast<size_t>(in.dst);
        if (program::isShapeClass(opClass)) {
            source[dst] = in.op == Opcode::Ground ? kGround : nextShape++;
        } else if (combine) {
            source[dst] = resultFromFirst(in.op, a, b) ? source[static_cast<size_t>(in.a)] : source[static_cast<size_t>(in.b)];
        } else if (opClass == program::OpClass::Post || opClass == program::OpClass::Texture ||
                   opClass == program::OpClass::ImageTexture || opClass == program::OpClass::FormulaImageTexture) {
            source[dst] = source[static_cast<size_t>(in.a)];
        } else if (opClass == program::OpClass::Constant) {
            source[dst] = kNothing;
        }
    }
    return source[static_cast<size_t>(program.result)];
}

std::optional<std::vector<int>> pathOfShape(const scene::Scene& scene, const program::Program& program, int shape) {
    if (shape < 0) return std::nullopt;
    std::vector<std::vector<int>> paths = primitivePaths(scene.root);
    auto shapes = std::count_if(program.code.begin(), program.code.end(), [](const Instruction& in) {
        return program::isShapeClass(program::opcodeInfo(in.op).opClass) && in.op != Opcode::Ground;
    });
    // a compiler that skipped or repeated a primitive would misname every pick
    if (static_cast<size_t>(shapes) != paths.size() || static_cast<size_t>(shape) >= paths.size()) return std::nullopt;
    return paths[static_cast<size_t>(shape)];
}

// Central differences at a march point, steps scaled with its distance from the eye.
glm::dvec3 gradientAt(const program::Program& program, const glm::dvec3& march) {
    f64::Kernel kernel(program, f64::FieldSource::Whole);
    f64::Scratch scratch(program);
    const double h = 1e-4 * (1.0 + std::sqrt(march.x * march.x + march.y * march.y + march.z * march.z));
    glm::dvec3 gradient(0.0);
    for (int axis = 0; axis < 3; ++axis) {
        glm::dvec3 step(0.0);
        step[axis] = h;
        gradient[axis] = kernel.map(scratch, march + step).d - kernel.map(scratch, march - step).d;
    }
    double length = std::sqrt(gradient.x * gradient.x + gradient.y * gradient.y + gradient.z * gradient.z);
    return length > 0 ? gradient / length : glm::dvec3(0.0, 1.0, 0.0);
}

}  // namespace

std::vector<std::vector<int>> primitivePaths(const scene::Node& root) {
    std::vector<std::vector<int>> paths;
    std::vector<int> path;
    collectPrimitives(root, scene::Visibility(root), path, paths);
    return paths;
}

double fieldDistance(const scene::Scene& scene, const program::Program& program, const glm::dvec3& world) {
    return evaluateDistance(program, world - scene::cameraFrame(scene.camera).eye, render::Precision::Float);
}

glm::dvec3 fieldNormal(const scene::Scene& scene, const program::Program& program, const glm::dvec3& world) {
    return gradientAt(program, world - scene::cameraFrame(scene.camera).eye);
}

std::optional<std::vector<int>> primitiveAt(const scene::Scene& scene, const program::Program& program,
                                            const glm::dvec3& world) {
    f32::Kernel kernel(program, f32::FieldSource::Whole);
    glm::dvec3 march = world - scene::cameraFrame(scene.camera).eye;
    return pathOfShape(scene, program, decidingShape(program, kernel, f32::vec3(march)));
}

PickResult pickPixel(const scene::Scene& scene, const program::Program& program, double x, double y) {
    f32::Kernel kernel(program, f32::FieldSource::Whole);
    f32::Scratch scratch(program);
    // the tracer's pixel coordinates count rows from the bottom, as gl_FragCoord
    float px = static_cast<float>(x), py = static_cast<float>(program.height - y);
    f32::SampleResult traced = kernel.trace(scratch, px, py);
    PickResult pick;
    pick.steps = traced.steps;
    pick.hit = traced.hit;
    if (!traced.hit) return pick;
    f32::Ray ray = kernel.ray(px, py);
    f32::vec3 march = ray.origin + ray.direction * traced.t;
    pick.t = traced.t;
    pick.position = glm::dvec3(march) + scene::cameraFrame(scene.camera).eye;
    pick.distance = kernel.map(scratch, march).d;
    pick.normal = gradientAt(program, glm::dvec3(march));
    int shape = decidingShape(program, kernel, march);
    pick.ground = shape == kGround;
    pick.node = pathOfShape(scene, program, shape);
    return pick;
}

PickResult pickViewCentre(const scene::Scene& scene) {
    program::Program program = program::compileScene(scene, {.aa = 1});
    return pickPixel(scene, program, 0.5 * program.width, 0.5 * program.height);
}

}  // namespace sdfwb::cpu
