#pragma once
// A scene compiled for rendering: a flat instruction list over point and sample
// registers, a parameter buffer, and the per-render settings. Both backends
// consume it: the CPU backend interprets the instructions, the GLSL backend
// generates straight-line code from them. The instruction list and the
// `structureKey` depend only on the scene's structure; all numbers live in
// `params`, so a parameter edit changes `params` and nothing else.

#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "expr/tape.h"
#include "program/opcodes.h"

namespace sdfwb::program {

// The language a formula is written in (docs/expression-language.md): a
// signed distance (sdf nodes) or an equation F = 0 (implicit and polynomial).
enum class FormulaLanguage { Sdf, Implicit };

// A user formula compiled for evaluation (engine/expr): its tape computes the
// value (SdfFormula) or the value and gradient (ImplicitFormula, and a
// distance formula's triplanar texture), from x, y, z.
struct FormulaCode {
    std::string source;
    FormulaLanguage language = FormulaLanguage::Sdf;
    bool withGradient = false;
    expr::Tape tape;
};

struct Instruction {
    Opcode op;
    int dst;       // register written (point register for Point ops, sample register otherwise)
    int a;         // first operand register
    int b;         // second operand register (Combine: sample, Post: point), else -1
    int param;     // first parameter slot
    int material;  // Shape: parameter slot of the material (4 slots), else -1
    int variant;   // SmoothUnion/Intersection/Difference: SMOOTH_* code; formulas: index into
                   // Program::formulas; else 0
};

// The parameter buffer's layout (scene-wide blocks, then materials) is the
// shared library's: sdf/glsl/parameter_blocks.glsl.

struct LightParams {
    glm::dvec3 direction;  // unit
    glm::dvec3 color;
    double softness;
};

struct TraceParams {
    int maxSteps;
    double maxDistance;
    double epsilon;
    double epsilonPerDistance;
    int shadowMode;     // SHADOW_* of the shared tracer
    int shadowSteps;
    int aoSamples;
    double aoDistance;
    int lightingModel;  // LIGHTING_*
    double stepRelaxation;
    int maxDepth;       // bounces of the ray tree
    glm::dvec3 ambientLight;
    glm::dvec3 background;
};

struct CameraParams {
    glm::dvec3 origin;  // march coordinates: the eye is the origin, see docs/rendering.md
    glm::dvec3 forward;
    glm::dvec3 right;
    glm::dvec3 up;
    double tanHalfFov;
};

struct Program {
    std::vector<Instruction> code;
    std::vector<glm::dvec4> params;
    std::vector<FormulaCode> formulas;
    int pointRegisters = 1;  // register 0 holds the evaluation point
    int sampleRegisters = 1;
    int result = 0;          // sample register holding the scene's distance
    // The ground plane's instructions run from here to the end, the last
    // uniting it with the root's result (engine/prune copies them for the
    // field outside its grid); -1: no ground.
    int groundStart = -1;

    // March-coordinate box enclosing the scene's root (the ground excluded);
    // rootBounded is false when some of it is unbounded (engine/prune).
    bool rootBounded = false;
    glm::dvec3 rootMin{0.0};
    glm::dvec3 rootMax{0.0};
    bool prune = true;  // debug switch: false evaluates the whole program everywhere
    // debug switch: false makes both backends carry materials through every
    // evaluation, not only those that read them (cpu/interpreter.inl,
    // gl/program_size.h's materialSampledApart)
    bool distanceOnlyEvaluation = true;

    CameraParams camera;
    TraceParams trace;
    std::vector<LightParams> lights;
    // Some material reflects or transmits and max_depth > 0: the backends
    // trace ray trees (sdf/glsl/ray_tree.glsl); structural, as GLSL compiles
    // the tree only then.
    bool secondaryRays = false;
    // The environment map (sdf/glsl/environment.glsl): ENVIRONMENT_* and its
    // image files, resolved against the scene's folder. The backends read the
    // images when they render (program/scene_images.h), not the compiler, so a
    // compile stays free of file reads; they also fill ENVIRONMENT_SLOT, whose
    // image size only the files know. Structural: whether there is an image.
    int environmentKind = 0;
    std::vector<std::string> environmentFiles;
    double environmentIntensity = 1.0;
    // Image textures (sdf/glsl/texture_lookup.glsl): each file once per way
    // it is read, resolved like the environment's, and the ImageTexture image
    // slots that name one; the backends fill those slots with the image's
    // place in their texel buffer when they read the files
    // (program/scene_images.h).
    struct TextureFile {
        std::string path;
        bool heights = false;  // a bump map's: its pixels are data, not colour (image::PixelValues)
        bool operator==(const TextureFile&) const = default;
    };
    struct TextureSlot {
        int slot;
        int file;  // index into textureFiles
    };
    std::vector<TextureFile> textureFiles;
    std::vector<TextureSlot> textureSlots;
    // Some material's bump map is an image: the tracer's material phase takes
    // four samples of its own around each hit to differentiate it. Structural.
    bool imageBumps = false;
    // Evaluations of the material phase per hit (sdf/glsl/tracer.glsl): 1,
    // the hit's material, or 5 with an image bump map.
    int materialSamplesPerHit() const;
    // The material fields the tracer's evaluations read (sdf/glsl/tracer.glsl,
    // traceMaterialReads) that are not 0 everywhere in this scene: the
    // shading always, the transparency where some material transmits
    // (shadows, an eye inside glass), the bump height where there is a
    // procedural bump map (the normal). A backend may evaluate the phases
    // that read none of these for their distances only.
    int materialReads() const;
    // Whether the driver may take the material phase's evaluations apart
    // from the others and run those on distances alone
    // (sdf/glsl/sample_driver.glsl): only the material phase reads materials,
    // rays do not branch (a ray tree's lanes would meet their material
    // samples out of step, doubling the loop back-edges llvmpipe counts) and
    // distance-only evaluation is on. Structural (structureKey).
    bool materialPhaseApart() const;
    int width = 0;
    int height = 0;
    int aa = 1;

    // Hash of the instructions, registers and formulas (prune grids are
    // keyed by it with the parameters they read).
    std::uint64_t codeKey() const;
    // Hash of everything that shapes generated code (codeKey and the
    // structural settings); equal keys can share a compiled shader.
    std::uint64_t structureKey() const;
};

}  // namespace sdfwb::program
