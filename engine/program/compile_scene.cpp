#include "program/compile_scene.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include "expr/derivative.h"
#include "expr/formula.h"
#include "program/bounds.h"
#include "program/rotation.h"
#include "program/scene_images.h"
#include "program/texture_mapping.h"
#include "scene/camera_frame.h"
#include "scene/visibility.h"
#include "sdf/shared.h"

namespace sdfwb::program {

using glm::dvec3;
using glm::dvec4;
using scene::Node;
using scene::NodeKind;

namespace {

// Scene enums become the shared library's integer codes by static_cast; these
// keep the two numberings one.
namespace codes = sdf::f32;
// The compiler packs parameter blocks with the shared packers, in double precision.
namespace shared = sdf::f64;
static_assert(static_cast<int>(scene::ShadowMode::None) == codes::SHADOW_NONE);
static_assert(static_cast<int>(scene::ShadowMode::Hard) == codes::SHADOW_HARD);
static_assert(static_cast<int>(scene::ShadowMode::Soft) == codes::SHADOW_SOFT);
static_assert(static_cast<int>(scene::ShadowMode::Improved) == codes::SHADOW_IMPROVED);
static_assert(static_cast<int>(scene::LightingModel::BlinnPhong) == codes::LIGHTING_BLINN_PHONG);
static_assert(static_cast<int>(scene::LightingModel::Phong) == codes::LIGHTING_PHONG);
static_assert(static_cast<int>(scene::GroundPattern::Plain) == codes::GROUND_PLAIN);
static_assert(static_cast<int>(scene::GroundPattern::Checker) == codes::GROUND_CHECKER);
static_assert(static_cast<int>(scene::GroundPattern::Grid) == codes::GROUND_GRID);
static_assert(static_cast<int>(scene::TexturePattern::None) == codes::TEXTURE_NONE);
static_assert(static_cast<int>(scene::TexturePattern::Checker) == codes::TEXTURE_CHECKER);
static_assert(static_cast<int>(scene::TexturePattern::Stripes) == codes::TEXTURE_STRIPES);
static_assert(static_cast<int>(scene::TexturePattern::Noise) == codes::TEXTURE_NOISE);
static_assert(static_cast<int>(scene::TexturePattern::Image) == codes::TEXTURE_IMAGE);
static_assert(static_cast<int>(scene::BumpPattern::None) == codes::BUMP_NONE);
static_assert(static_cast<int>(scene::BumpPattern::Noise) == codes::BUMP_NOISE);
static_assert(static_cast<int>(scene::BumpPattern::Waves) == codes::BUMP_WAVES);
static_assert(static_cast<int>(scene::BumpPattern::Image) == codes::BUMP_IMAGE);
static_assert(static_cast<int>(scene::EnvironmentMapKind::Color) == codes::ENVIRONMENT_COLOR);
static_assert(static_cast<int>(scene::EnvironmentMapKind::Equirect) == codes::ENVIRONMENT_EQUIRECT);
static_assert(static_cast<int>(scene::EnvironmentMapKind::Sphere) == codes::ENVIRONMENT_SPHERE);
static_assert(static_cast<int>(scene::EnvironmentMapKind::Box) == codes::ENVIRONMENT_BOX);
static_assert(static_cast<int>(scene::SmoothVariant::Polynomial) == codes::SMOOTH_POLYNOMIAL);
static_assert(static_cast<int>(scene::SmoothVariant::Exponential) == codes::SMOOTH_EXPONENTIAL);
static_assert(static_cast<int>(scene::SmoothVariant::Power) == codes::SMOOTH_POWER);
static_assert(static_cast<int>(scene::SmoothVariant::Root) == codes::SMOOTH_ROOT);
// Epsilon modes have no shared code: the compiler turns them into epsilon and
// epsilonPerDistance below.

// Twist and bend stretch space: the field's Lipschitz constant grows to about
// sqrt(1 + (k r)^2) at radius r from the axis. Steps are scaled by its inverse
// over the child's bounds, never below this floor (an unbounded child).
constexpr double kMinStepFactor = 0.05;

// A primitive's opcode and parameter slots, packed from its fields.
struct ShapeCode {
    Opcode op;
    std::vector<dvec4> params;
};

ShapeCode sphereCode(const Node& n) { return {Opcode::Sphere, {dvec4(n.real("radius"), 0, 0, 0)}}; }
ShapeCode boxCode(const Node& n) { return {Opcode::Box, {dvec4(n.vec3("half_extents"), 0)}}; }
ShapeCode roundBoxCode(const Node& n) {
    dvec3 h = n.vec3("half_extents");
    double r = std::min(n.real("radius"), std::min(h.x, std::min(h.y, h.z)));
    return {Opcode::RoundBox, {dvec4(h, r)}};
}
ShapeCode planeCode(const Node& n) {
    return {Opcode::Plane, {dvec4(glm::normalize(n.vec3("normal")), n.real("offset"))}};
}
ShapeCode torusCode(const Node& n) {
    return {Opcode::Torus, {dvec4(n.real("major_radius"), n.real("minor_radius"), 0, 0)}};
}
ShapeCode coneCode(const Node& n) {
    double angle = n.real("angle") * M_PI / 180.0;
    return {Opcode::Cone, {dvec4(std::sin(angle), std::cos(angle), n.real("height"), 0)}};
}
ShapeCode ellipsoidCode(const Node& n) { return {Opcode::Ellipsoid, {dvec4(n.vec3("radii"), 0)}}; }
ShapeCode cylinderCode(const Node& n) {
    return {Opcode::Cylinder, {dvec4(n.real("radius"), n.real("half_height"), 0, 0)}};
}
ShapeCode capsuleCode(const Node& n) {
    return {Opcode::Capsule, {dvec4(n.vec3("a"), n.real("radius")), dvec4(n.vec3("b"), 0)}};
}

// Operators that only move the evaluation point: opcode and slots.
ShapeCode elongateCode(const Node& n) { return {Opcode::Elongate, {dvec4(n.vec3("h"), 0)}}; }
ShapeCode mirrorCode(const Node& n) {
    const std::string& axes = n.text("axes");
    dvec3 mask(axes.find('x') != std::string::npos, axes.find('y') != std::string::npos,
               axes.find('z') != std::string::npos);
    return {Opcode::Mirror, {dvec4(mask, 0)}};
}
ShapeCode repeatCode(const Node& n) {
    return {Opcode::Repeat, {dvec4(n.vec3("spacing"), 0), dvec4(n.vec3("counts"), 0)}};
}
ShapeCode repeatInfiniteCode(const Node& n) { return {Opcode::RepeatInfinite, {dvec4(n.vec3("period"), 0)}}; }

// The ground's height in march coordinates (the eye at 0): the ground's
// instruction and the trace settings both carry it.
double groundHeightFromEye(const scene::Ground& ground, const dvec3& eye) { return ground.height - eye.y; }

class Compiler {
public:
    explicit Compiler(const scene::Scene& scene) : scene_(scene), visibility_(scene.root) {
        // the scene-wide blocks come first; compileScene fills them
        program_.params.resize(static_cast<size_t>(shared::MATERIAL_SLOT), dvec4(0.0));
        defaultMaterialSlot_ = addMaterial(scene::defaultMaterial());
        for (size_t i = 0; i < scene.materials.size(); ++i) {
            const scene::Material& m = scene.materials[i];
            materialSlots_[m.name] = addMaterial(m);
            materialIndex_.emplace(m.name, i);
        }
    }

    Program& program() { return program_; }

    // Compiles `node` evaluated at P[point] + offset; returns the sample register.
    int compile(const Node& node, int point, dvec3 offset);

    // The pattern is evaluated on march x, z plus the eye's: the eye's x and z
    // are reduced here, in double, modulo the pattern's period (two cells, a
    // checker's), so the float sum stays small wherever the scene sits (at
    // 1e5 a float ulp is 0.008 and grid lines came out fat and uneven).
    // footprintPerDistance: the width one sample spans at distance 1, by
    // which the shared code box-filters the pattern (material.glsl).
    // A texture or bump map of the ground's material is mapped as on a plane
    // primitive facing +y at the world's origin: (u, v) run along world x
    // and z, so the texture stays on the floor as the eye moves.
    int compileGround(const scene::Ground& ground, const dvec3& eye, double footprintPerDistance, bool alongRay) {
        scene::Node plane = scene::Node::make(scene::NodeKind::Plane);
        plane.set("material", ground.material);
        const bool textured = hasTextureOrBump(plane);
        dvec3 worldOffset = eye;
        int world = textured ? materialize(0, worldOffset) : 0;
        int s = allocSample();
        dvec3 patternEye = eye;
        if (ground.cellSize > 0) {
            patternEye.x = reduceModulo(eye.x, 2.0 * ground.cellSize);
            patternEye.z = reduceModulo(eye.z, 2.0 * ground.cellSize);
        }
        double pattern = static_cast<double>(ground.pattern);
        int param = addParams({dvec4(groundHeightFromEye(ground, eye), pattern, footprintPerDistance, alongRay ? 1.0 : 0.0),
                               dvec4(patternEye, ground.cellSize), dvec4(ground.secondColor, ground.lineWidth)});
        emit({Opcode::Ground, s, 0, -1, param, materialSlot(ground.material), 0});
        if (textured) {
            texture(plane, s, world);
            if (world != 0) releasePoint();  // none taken with the eye at the origin
        }
        return s;
    }

    void combine(Opcode op, int accumulator, int other, int param, int variant) {
        emit({op, accumulator, accumulator, other, param, -1, variant});
        releaseSample();
    }

    // ---- one entry per node kind (kCompileRules) ----
    template <ShapeCode (*Code)(const Node&)>
    int primitive(const Node& node, int point, dvec3 offset) {
        int p = materialize(point, offset);
        int s = allocSample();
        ShapeCode shape = Code(node);
        emit({shape.op, s, p, -1, addParams(shape.params), materialSlot(node.text("material")), 0});
        texture(node, s, p);
        if (p != point) releasePoint();
        return s;
    }

    int sdfFormula(const Node& node, int point, dvec3 offset) {
        int p = materialize(point, offset);
        int s = allocSample();
        emit({Opcode::SdfFormula, s, p, -1, -1, materialSlot(node.text("material")),
              addFormula(node.text("formula"), FormulaLanguage::Sdf, false)});
        texture(node, s, p);
        if (p != point) releasePoint();
        return s;
    }

    // Implicit and polynomial surfaces: F = 0 inside a box, value and gradient from the tape.
    int implicitFormula(const Node& node, int point, dvec3 offset) {
        int p = materialize(point, offset);
        int s = allocSample();
        dvec3 lo = node.vec3("bounds_min"), hi = node.vec3("bounds_max");
        int param = addParams({dvec4((lo + hi) * 0.5, node.real("max_step")),
                               dvec4((hi - lo) * 0.5, node.real("sheet_thickness") * 0.5)});
        int material = materialSlot(node.text("material"));
        int formula = addFormula(node.text("formula"), FormulaLanguage::Implicit, true);
        emit({Opcode::ImplicitFormula, s, p, -1, param, material, formula});
        texture(node, s, p);
        if (p != point) releasePoint();
        return s;
    }

    template <Opcode Op>
    int hardBoolean(const Node& node, int point, dvec3 offset) {
        return fold(node, point, offset, Op, -1, 0);
    }

    template <Opcode Op>
    int smoothBoolean(const Node& node, int point, dvec3 offset) {
        if (node.children.empty()) return fold(node, point, offset, Op, -1, 0);
        const scene::KindSpec& spec = kindSpec(node.kind);
        const auto& choices = spec.fields[static_cast<size_t>(fieldIndex(spec, "variant"))].choices;
        int variant = static_cast<int>(std::find(choices.begin(), choices.end(), node.text("variant")) - choices.begin());
        // the first child is compiled before the parameters are added, as the slots have always been laid out
        int accumulator = compile(node.children[0], point, offset);
        int param = addParams({dvec4(node.real("k"), node.real("exponent"), 0, 0)});
        return foldRest(node, point, offset, Op, accumulator, param, variant);
    }

    int translate(const Node& node, int point, dvec3 offset) {
        return compile(node.children.at(0), point, offset - node.vec3("offset"));
    }

    int rotate(const Node& node, int point, dvec3 offset) {
        glm::dmat3 inverse = glm::transpose(rotationFromAngles(node.vec3("angles")));
        // rows of the inverse rotation
        int r = pointOp(Opcode::Rotate, point,
                        {dvec4(inverse[0][0], inverse[1][0], inverse[2][0], 0),
                         dvec4(inverse[0][1], inverse[1][1], inverse[2][1], 0),
                         dvec4(inverse[0][2], inverse[1][2], inverse[2][2], 0)});
        int s = compile(node.children.at(0), r, inverse * offset);
        releasePoint();
        return s;
    }

    int scale(const Node& node, int point, dvec3 offset) {
        double factor = node.real("factor");
        int r = pointOp(Opcode::Scale, point, {dvec4(factor, 0, 0, 0)});
        double outerScale = objectScale_;
        objectScale_ *= factor;
        int s = compile(node.children.at(0), r, offset / factor);
        objectScale_ = outerScale;
        releasePoint();
        postOp(Opcode::ScaleDistance, s, r, {dvec4(factor, 0, 0, 0)});
        return s;
    }

    int round(const Node& node, int point, dvec3 offset) {
        int s = compile(node.children.at(0), point, offset);
        postOp(Opcode::RoundDistance, s, point, {dvec4(node.real("radius"), 0, 0, 0)});
        return s;
    }

    int displace(const Node& node, int point, dvec3 offset) {
        int p = materialize(point, offset);
        int s = compile(node.children.at(0), p, dvec3(0.0));
        double amplitude = node.real("amplitude"), frequency = node.real("frequency");
        // |grad pattern| <= |a f| sqrt(3): scale steps so the field stays 1-Lipschitz
        double factor = 1.0 / (1.0 + std::abs(amplitude * frequency) * std::sqrt(3.0));
        postOp(Opcode::Displace, s, p, {dvec4(amplitude, frequency, factor, 0)});
        if (p != point) releasePoint();
        return s;
    }

    // Twist and bend: the point moves, and steps shrink by the Lipschitz bound over the child's bounds.
    template <Opcode Op>
    int warp(const Node& node, int point, dvec3 offset) {
        const Node& child = node.children.at(0);
        int p = materialize(point, offset);
        double k = node.real("k");
        int r = pointOp(Op, p, {dvec4(k, 0, 0, 0)});
        Bounds b = nodeBounds(child);
        double radius = Op == Opcode::Twist ? b.radiusAboutY() : b.radiusAboutZ();
        double factor = stepFactor(k, b.infinite ? INFINITY : radius);
        return finishPointOp(child, point, p, r, factor);
    }

    // Shifting by whole periods changes nothing, so the pending offset (the
    // eye, for a repetition about the world origin) is reduced to less than a
    // period before it becomes a float: far from the origin the cells kept
    // float's accuracy of the eye's position (0.008 at 1e5).
    int repeatInfinite(const Node& node, int point, dvec3 offset) {
        dvec3 period = node.vec3("period");
        for (int axis = 0; axis < 3; ++axis) {
            if (period[axis] != 0) offset[axis] = reduceModulo(offset[axis], std::abs(period[axis]));
        }
        return pointTransform<repeatInfiniteCode>(node, point, offset);
    }

    template <ShapeCode (*Code)(const Node&)>
    int pointTransform(const Node& node, int point, dvec3 offset) {
        int p = materialize(point, offset);
        ShapeCode transform = Code(node);
        int r = allocPoint();
        emit({transform.op, r, p, -1, addParams(transform.params), -1, 0});
        return finishPointOp(node.children.at(0), point, p, r, 1.0);
    }

    // The width one sample spans at distance 1 (set before compiling): the
    // footprint by which the shared code filters textures and the ground.
    double footprintPerDistance = 0.0;

private:
    // A primitive whose material has a texture gets its sample textured at
    // its object-space point P[p] (texture.glsl), and one with a bump map its
    // bump height there; a scene without either compiles to the same code as
    // before they existed. The footprint is
    // converted to texture units: world widths shrink by the scale nodes
    // above the primitive (objectScale_), then by the texture's scale.
    const scene::Material& materialOf(const Node& node) const {
        auto it = materialIndex_.find(node.text("material"));
        return it == materialIndex_.end() ? defaultMaterial_ : scene_.materials[it->second];
    }
    bool hasTextureOrBump(const Node& node) const {
        const scene::Material& m = materialOf(node);
        return m.texture != scene::TexturePattern::None || m.bump != scene::BumpPattern::None;
    }

    void texture(const Node& node, int sample, int point) {
        const scene::Material& m = materialOf(node);
        const Instruction shape = program_.code.back();  // the primitive just emitted
        int gradient = -1;  // a formula's tape with its gradient, once, for its triplanar images
        if (m.texture == scene::TexturePattern::Image) {
            imageTexture(node, shape, gradient, {m.textureImage, m.textureScale, colorRole(m), 0.0, filtered(m)}, sample, point);
        } else if (m.texture != scene::TexturePattern::None) {
            double perUnit = 1.0 / m.textureScale;
            double footprint = filtered(m) * perUnit / objectScale_;
            int param = addParams(
                {dvec4(static_cast<double>(m.texture), perUnit, footprint, specular(m)), dvec4(m.textureColor, 0)});
            emit({Opcode::Texture, sample, sample, point, param, -1, 0});
        }
        // the depth in object units, like the pattern: scale nodes scale the bumps too
        if (m.bump == scene::BumpPattern::Image) {
            program_.imageBumps = true;
            imageTexture(node, shape, gradient, {m.bumpImage, m.bumpScale, codes::IMAGE_AS_BUMP, m.bumpDepth * objectScale_, filtered(m)},
                         sample, point);
        } else if (m.bump != scene::BumpPattern::None) {
            double perUnit = 1.0 / m.bumpScale;
            double footprint = filtered(m) * perUnit / objectScale_;
            int param = addParams({dvec4(static_cast<double>(m.bump), perUnit, footprint, m.bumpDepth * objectScale_)});
            emit({Opcode::Bump, sample, sample, point, param, -1, 0});
        }
    }

    // An image on a primitive: a colour texture, or with a depth a bump map
    // whose height is the image's grey value times the depth
    // (sdf/glsl/texture_lookup.glsl).
    struct ImageUse {
        const std::string& file;  // as the material names it
        double tileSize;          // the material's texture or bump scale
        int role;                 // IMAGE_AS_* of the shared texture lookup
        double bumpDepth;         // of a bump map
        double footprint;         // per distance: filtered(m)
    };

    // The image's place in the texel buffer (the last slot) is left for the
    // backends to fill when they read the file (program/scene_images.h).
    // A formula has no parametrization: it is mapped triplanar, by its
    // gradient (an implicit surface's own tape has it; a distance formula
    // gets a second tape with one).
    void imageTexture(const Node& node, const Instruction& shape, int& gradient, const ImageUse& use, int sample,
                      int point) {
        const Program::TextureFile file{sceneFilePath(scene_, use.file).string(), use.role == codes::IMAGE_AS_BUMP};
        auto known = std::find(program_.textureFiles.begin(), program_.textureFiles.end(), file);
        if (known == program_.textureFiles.end()) known = program_.textureFiles.insert(known, file);
        const int fileIndex = static_cast<int>(known - program_.textureFiles.begin());
        if (opcodeInfo(shape.op).opClass == OpClass::FormulaShape ||
            opcodeInfo(shape.op).opClass == OpClass::FormulaSample) {
            if (gradient < 0) {
                gradient = shape.op == Opcode::ImplicitFormula
                               ? shape.variant
                               : addFormula(node.text("formula"), FormulaLanguage::Sdf, true);
            }
            double tiles = 1.0 / use.tileSize;
            int param = addParams(
                {dvec4(tiles, use.footprint * tiles / objectScale_, use.role, use.bumpDepth), dvec4(0.0)});
            program_.textureSlots.push_back({param + 1, fileIndex});
            emit({Opcode::TriplanarTexture, sample, sample, point, param, -1, gradient});
            return;
        }
        TextureMapping map = textureMapping(node, use.tileSize);
        double footprint = use.footprint * map.uvPerUnit / objectScale_;
        int param = addParams({dvec4(map.mapping, footprint, use.role, use.bumpDepth), map.s0, map.s1, dvec4(0.0)});
        program_.textureSlots.push_back({param + 3, fileIndex});
        emit({Opcode::ImageTexture, sample, sample, point, param, -1, 0});
    }

    // The footprint per distance the material's textures and bump maps are
    // filtered over: 0 reads images at level 0 and patterns unfiltered.
    double filtered(const scene::Material& m) const { return m.textureFiltering ? footprintPerDistance : 0.0; }

    // The textures' flag for the specular colour, as their instructions read it.
    static double specular(const scene::Material& m) { return m.textureSpecular ? 1.0 : 0.0; }
    static int colorRole(const scene::Material& m) {
        return m.textureSpecular ? codes::IMAGE_AS_COLOR_AND_SPECULAR : codes::IMAGE_AS_COLOR;
    }

    // x minus the nearest multiple of period (period > 0), exact in double for
    // the magnitudes of a scene.
    static double reduceModulo(double x, double period) { return x - period * std::floor(x / period + 0.5); }

    int addParams(std::initializer_list<dvec4> values) { return addParams(std::vector<dvec4>(values)); }
    int addParams(const std::vector<dvec4>& values) {
        int first = static_cast<int>(program_.params.size());
        program_.params.insert(program_.params.end(), values.begin(), values.end());
        return first;
    }

    int addMaterial(const scene::Material& m) {
        shared::Material packed{.ambient = m.ambient,
                                .diffuse = m.diffuse,
                                .specular = m.specular,
                                .shininess = m.shininess,
                                .emission = m.emission,
                                .emissionStrength = m.emissionStrength,
                                .reflectivity = m.reflectivity,
                                .reflectionColor = m.reflectionColor,
                                .transparency = m.transparency,
                                .transmissionColor = m.transmissionColor,
                                .ior = m.ior,
                                .fresnel = m.fresnel ? 1.0 : 0.0,
                                .bump = 0.0};  // a sample's, set by a Bump instruction: not packed
        int first = static_cast<int>(program_.params.size());
        for (int i = 0; i < shared::MATERIAL_SLOTS; ++i) program_.params.push_back(shared::materialSlot(packed, i));
        return first;
    }

    int addFormula(const std::string& source, FormulaLanguage language, bool withGradient) {
        program_.formulas.push_back(compileFormula(source, language, withGradient));
        return static_cast<int>(program_.formulas.size()) - 1;
    }

    int materialSlot(const std::string& name) {
        auto it = materialSlots_.find(name);
        return it == materialSlots_.end() ? defaultMaterialSlot_ : it->second;
    }

    void emit(const Instruction& instruction) { program_.code.push_back(instruction); }

    int allocPoint() {
        int r = pointTop_++;
        program_.pointRegisters = std::max(program_.pointRegisters, pointTop_);
        return r;
    }
    void releasePoint() { --pointTop_; }
    int allocSample() {
        int r = sampleTop_++;
        program_.sampleRegisters = std::max(program_.sampleRegisters, sampleTop_);
        return r;
    }
    void releaseSample() { --sampleTop_; }

    // Applies a pending offset as an instruction; returns the register to use.
    // The caller releases the returned register if it differs from `point`.
    int materialize(int point, dvec3& offset) {
        if (offset == dvec3(0.0)) {
            return point;
        }
        int translated = allocPoint();
        emit({Opcode::Translate, translated, point, -1, addParams({dvec4(offset, 0)}), -1, 0});
        offset = dvec3(0.0);
        return translated;
    }

    int pointOp(Opcode op, int point, std::initializer_list<dvec4> params) {
        int r = allocPoint();
        emit({op, r, point, -1, addParams(params), -1, 0});
        return r;
    }

    void postOp(Opcode op, int sample, int point, std::initializer_list<dvec4> params) {
        emit({op, sample, sample, point, addParams(params), -1, 0});
    }

    // The child of a point operator at P[r]; then the registers are released and
    // a step factor below 1 is applied.
    int finishPointOp(const Node& child, int point, int p, int r, double factor) {
        int s = compile(child, r, dvec3(0.0));
        releasePoint();
        if (p != point) releasePoint();
        if (factor < 1.0) {
            postOp(Opcode::StepScale, s, point, {dvec4(factor, 0, 0, 0)});
        }
        return s;
    }

    // Booleans fold their children left to right; no children is "nothing".
    int fold(const Node& node, int point, dvec3 offset, Opcode op, int param, int variant) {
        if (node.children.empty()) return emptySpace();
        int accumulator = compile(node.children[0], point, offset);
        return foldRest(node, point, offset, op, accumulator, param, variant);
    }

    // "Nothing": an empty boolean, a hidden node.
    int emptySpace() {
        int s = allocSample();
        emit({Opcode::Empty, s, -1, -1, -1, -1, 0});
        return s;
    }

    int foldRest(const Node& node, int point, dvec3 offset, Opcode op, int accumulator, int param, int variant) {
        for (size_t i = 1; i < node.children.size(); ++i) {
            int other = compile(node.children[i], point, offset);
            combine(op, accumulator, other, param, variant);
        }
        return accumulator;
    }

    double stepFactor(double k, double radius) const {
        if (!std::isfinite(radius)) {
            return kMinStepFactor;
        }
        return std::max(kMinStepFactor, 1.0 / std::sqrt(1.0 + k * k * radius * radius));
    }

    const scene::Scene& scene_;
    scene::Visibility visibility_;
    Program program_;
    std::map<std::string, int> materialSlots_;
    std::map<std::string, size_t> materialIndex_;  // into scene_.materials
    scene::Material defaultMaterial_ = scene::defaultMaterial();
    double objectScale_ = 1.0;  // product of the scale factors above the node being compiled
    int defaultMaterialSlot_ = 0;
    int pointTop_ = 1;
    int sampleTop_ = 0;
};

// How each node kind compiles, in NodeKind order (checked below): a new kind
// without an entry does not build.
struct CompileRule {
    NodeKind kind;
    int (Compiler::*compile)(const Node&, int, dvec3);
};

using enum NodeKind;
constexpr std::array<CompileRule, scene::kNodeKindCount> kCompileRules = {{
    {Sphere, &Compiler::primitive<sphereCode>},
    {Box, &Compiler::primitive<boxCode>},
    {RoundBox, &Compiler::primitive<roundBoxCode>},
    {Plane, &Compiler::primitive<planeCode>},
    {Torus, &Compiler::primitive<torusCode>},
    {Cone, &Compiler::primitive<coneCode>},
    {Ellipsoid, &Compiler::primitive<ellipsoidCode>},
    {Cylinder, &Compiler::primitive<cylinderCode>},
    {Capsule, &Compiler::primitive<capsuleCode>},
    {Union, &Compiler::hardBoolean<Opcode::Union>},
    {Intersection, &Compiler::hardBoolean<Opcode::Intersection>},
    {Difference, &Compiler::hardBoolean<Opcode::Difference>},
    {SmoothUnion, &Compiler::smoothBoolean<Opcode::SmoothUnion>},
    {SmoothIntersection, &Compiler::smoothBoolean<Opcode::SmoothIntersection>},
    {SmoothDifference, &Compiler::smoothBoolean<Opcode::SmoothDifference>},
    {Translate, &Compiler::translate},
    {Rotate, &Compiler::rotate},
    {Scale, &Compiler::scale},
    {Twist, &Compiler::warp<Opcode::Twist>},
    {Bend, &Compiler::warp<Opcode::Bend>},
    {NodeKind::Round, &Compiler::round},
    {NodeKind::Displace, &Compiler::displace},
    {NodeKind::Elongate, &Compiler::pointTransform<elongateCode>},
    {NodeKind::Mirror, &Compiler::pointTransform<mirrorCode>},
    {NodeKind::Repeat, &Compiler::pointTransform<repeatCode>},
    {NodeKind::RepeatInfinite, &Compiler::repeatInfinite},
    {Sdf, &Compiler::sdfFormula},
    {Implicit, &Compiler::implicitFormula},
    {Polynomial, &Compiler::implicitFormula},
}};
static_assert(scene::inKindOrder(kCompileRules), "kCompileRules must list every node kind in NodeKind order");

int Compiler::compile(const Node& node, int point, dvec3 offset) {
    if (!visibility_.draws(node)) return emptySpace();
    return (this->*kCompileRules[static_cast<size_t>(node.kind)].compile)(node, point, offset);
}

// The trace settings, camera and lights into their blocks at the start of the
// parameter buffer (sdf/glsl/parameter_blocks.glsl). Settings only the tracer
// reads come straight from the scene's; Program::trace mirrors the rest for the
// host (loop bounds, reports).
// The march takes the ground plane along the ray (tracer.glsl's groundAhead,
// instGround's step above the plane): the trace settings and the ground's
// instruction both say so.
bool groundAlongRay(const scene::Scene& scene) {
    return scene.environment.ground.enabled && scene.render.tracing == scene::Tracing::Bounded;
}

void writeSceneBlocks(Program& program, const scene::Scene& scene, const dvec3& eye) {
    const scene::RenderSettings& r = scene.render;
    const scene::Ground& ground = scene.environment.ground;
    const TraceParams& t = program.trace;
    // shadow rays end, the march skips empty space and a floor far from the
    // objects is shaded as a plane by the scene's bounds (tracer.glsl's
    // shadowRayClear, emptyMarchAhead, onlyGroundWithin)
    bool bounded = program.rootBounded && r.tracing == scene::Tracing::Bounded;
    int boundsUse = bounded ? shared::BOUNDS_END_SHADOW_RAYS | shared::BOUNDS_SKIP_MARCH : 0;
    const scene::Material* groundMaterial = scene.findMaterial(ground.material);
    bool bumpedGround = groundMaterial != nullptr && groundMaterial->bump != scene::BumpPattern::None;
    if (bounded && ground.enabled && !bumpedGround) {
        boundsUse |= shared::BOUNDS_FLAT_GROUND;
    }
    shared::TraceSettings settings{.maxSteps = t.maxSteps,
                                   .maxDistance = t.maxDistance,
                                   .epsilon = t.epsilon,
                                   .epsilonPerDistance = t.epsilonPerDistance,
                                   .shadowMode = t.shadowMode,
                                   .shadowSteps = t.shadowSteps,
                                   .aoSamples = t.aoSamples,
                                   .aoDistance = t.aoDistance,
                                   .lightingModel = t.lightingModel,
                                   .relaxation = t.stepRelaxation,
                                   .lightCount = static_cast<int>(program.lights.size()),
                                   .exposure = r.exposure,
                                   .ambientLight = t.ambientLight,
                                   .background = t.background,
                                   .maxDepth = t.maxDepth,
                                   .rayWeightCutoff = r.rayWeightCutoff,
                                   .groundPlane = groundAlongRay(scene) ? 1 : 0,
                                   .groundHeight = ground.enabled ? groundHeightFromEye(ground, eye) : 0.0,
                                   .boundsUse = boundsUse,
                                   .boundsCenter = dvec3(0.0),
                                   .boundsRadius = 0.0};
    if (bounded) {
        // the root's box (march coordinates) in a sphere, widened by far more
        // than the rounding of its centre and radius to float
        settings.boundsCenter = 0.5 * (program.rootMin + program.rootMax);
        double radius = 0.5 * glm::length(program.rootMax - program.rootMin);
        settings.boundsRadius = radius + 1e-5 * (radius + glm::length(settings.boundsCenter));
    }
    for (int i = 0; i < shared::TRACE_SLOTS; ++i) {
        program.params[static_cast<size_t>(shared::TRACE_SLOT + i)] = shared::traceSettingsSlot(settings, i);
    }
    const CameraParams& c = program.camera;
    shared::Camera camera{
        .origin = c.origin, .forward = c.forward, .right = c.right, .up = c.up, .tanHalfFov = c.tanHalfFov};
    for (int i = 0; i < shared::CAMERA_SLOTS; ++i) {
        program.params[static_cast<size_t>(shared::CAMERA_SLOT + i)] = shared::cameraSlot(camera, i);
    }
    static_assert(scene::kMaxLights == shared::MAX_LIGHTS);
    for (size_t l = 0; l < program.lights.size(); ++l) {
        const LightParams& light = program.lights[l];
        shared::Light packed{.direction = light.direction, .color = light.color, .softness = light.softness};
        for (int i = 0; i < shared::LIGHT_SLOTS; ++i) {
            size_t slot = static_cast<size_t>(shared::LIGHT_SLOT + shared::LIGHT_SLOTS * static_cast<int>(l) + i);
            program.params[slot] = shared::lightSlot(packed, i);
        }
    }
}

}  // namespace

FormulaCode compileFormula(const std::string& source, FormulaLanguage language, bool withGradient) {
    expr::SpaceFormula formula =
        language == FormulaLanguage::Implicit ? expr::compileImplicit(source) : expr::compileSdf(source);
    std::vector<expr::NodeId> outputs = {formula.value};
    if (withGradient) {
        std::array<expr::NodeId, 3> gradient = expr::gradient(formula.graph, formula.value);
        outputs.insert(outputs.end(), gradient.begin(), gradient.end());
    }
    return {source, language, withGradient, expr::Tape(formula.graph, outputs)};
}

Program compileScene(const scene::Scene& scene, const CompileOptions& options) {
    Compiler compiler(scene);
    scene::CameraFrame frame = scene::cameraFrame(scene.camera);
    const scene::RenderSettings& r = scene.render;
    int width = options.width > 0 ? options.width : r.width;
    int height = options.height > 0 ? options.height : r.height;
    int aa = options.aa > 0 ? options.aa : r.aa;
    // at distance t one sub-sample spans t * 2 tan(fov/2) / (height * aa)
    double footprintPerDistance = 2.0 * frame.tanHalfFov / (height * aa);
    compiler.footprintPerDistance = footprintPerDistance;
    int result = compiler.compile(scene.root, 0, frame.eye);
    int groundStart = -1;
    if (scene.environment.ground.enabled) {
        groundStart = static_cast<int>(compiler.program().code.size());
        int ground =
            compiler.compileGround(scene.environment.ground, frame.eye, footprintPerDistance, groundAlongRay(scene));
        compiler.combine(Opcode::Union, result, ground, -1, 0);
    }
    Program program = std::move(compiler.program());
    program.result = result;
    program.groundStart = groundStart;
    Bounds root = nodeBounds(scene.root);
    program.rootBounded = root.finite();
    if (program.rootBounded) {
        program.rootMin = root.min - frame.eye;
        program.rootMax = root.max - frame.eye;
    }
    program.prune = options.prune;

    program.width = width;
    program.height = height;
    program.aa = aa;
    program.camera = {dvec3(0.0), frame.forward, frame.right, frame.up, frame.tanHalfFov};

    TraceParams& t = program.trace;
    t.maxSteps = r.maxSteps;
    t.maxDistance = r.maxDistance;
    if (r.epsilonMode == scene::EpsilonMode::Pixel) {
        // r.epsilon sub-sample footprints (footprintPerDistance above, written
        // out so the bits stay as they were), so higher AA also resolves finer
        // detail instead of averaging silhouettes dilated by a whole pixel's epsilon
        t.epsilon = 0.0;
        t.epsilonPerDistance = r.epsilon * 2.0 * frame.tanHalfFov / (program.height * program.aa);
    } else {
        t.epsilon = r.epsilon;
        t.epsilonPerDistance = 0.0;
    }
    t.shadowMode = static_cast<int>(r.shadows);
    t.shadowSteps = r.shadowSteps;
    t.aoSamples = r.aoSamples;
    t.aoDistance = r.aoDistance;
    t.lightingModel = static_cast<int>(r.lighting);
    t.stepRelaxation = r.stepRelaxation;
    t.maxDepth = r.maxDepth;
    static_assert(scene::kMaxTraceDepth == shared::MAX_TRACE_DEPTH);
    program.secondaryRays = r.maxDepth > 0 && scene.hasMirrorsOrGlass();
    t.ambientLight = scene.environment.ambient;
    t.background = scene.environment.background;
    program.environmentKind = static_cast<int>(scene.environment.map);
    for (const SceneImageFile& file : environmentFiles(scene)) program.environmentFiles.push_back(file.path.string());
    program.environmentIntensity = scene.environment.intensity;
    for (const scene::Light& light : scene.lights) {
        program.lights.push_back({glm::normalize(light.direction), light.color, light.softness});
    }
    writeSceneBlocks(program, scene, frame.eye);
    return program;
}

int Program::materialSamplesPerHit() const { return imageBumps ? shared::HIT_MATERIAL_SAMPLE + 1 : 1; }

int Program::materialReads() const {
    auto transmits = [&](int slot) {
        auto q = [&](int i) { return params[static_cast<size_t>(slot + i)]; };
        return shared::materialFromSlots(q(0), q(1), q(2), q(3), q(4), q(5)).transparency > 0.0;
    };
    // the default material: Empty's, and the pruning grid's outside box's (prune/prune_grid.h)
    bool transparency = transmits(shared::MATERIAL_SLOT) ||
                        std::any_of(code.begin(), code.end(),
                                    [&](const Instruction& in) { return in.material >= 0 && transmits(in.material); });
    bool bump = std::any_of(code.begin(), code.end(), [](const Instruction& in) { return in.op == Opcode::Bump; });
    return shared::MATERIAL_READS_SHADING | (transparency ? shared::MATERIAL_READS_TRANSPARENCY : 0) |
           (bump ? shared::MATERIAL_READS_BUMP : 0);
}

bool Program::materialPhaseApart() const {
    return distanceOnlyEvaluation && !secondaryRays && shared::materialPhaseApart(materialReads());
}

namespace {

// FNV-1a over 64-bit values, a byte at a time.
struct KeyHash {
    std::uint64_t hash = 1469598103934665603ull;
    void mix(std::int64_t value) {
        for (int i = 0; i < 8; ++i) {
            hash ^= static_cast<std::uint64_t>(value >> (8 * i)) & 0xffu;
            hash *= 1099511628211ull;
        }
    }
};

}  // namespace

std::uint64_t Program::codeKey() const {
    KeyHash key;
    for (const Instruction& in : code) {
        key.mix(static_cast<int>(in.op));
        key.mix(in.dst);
        key.mix(in.a);
        key.mix(in.b);
        key.mix(in.param);
        key.mix(in.material);
        key.mix(in.variant);
    }
    key.mix(pointRegisters);
    key.mix(sampleRegisters);
    key.mix(result);
    for (const FormulaCode& formula : formulas) {
        key.mix(static_cast<int>(formula.language));
        key.mix(formula.withGradient);
        for (char c : formula.source) key.mix(c);
    }
    return key.hash;
}

std::uint64_t Program::structureKey() const {
    KeyHash key{codeKey()};
    key.mix(secondaryRays);
    key.mix(imageBumps);
    // a material's transparency turning on or off in a scene without ray
    // trees changes the driver's loops
    key.mix(materialPhaseApart());
    key.mix(environmentKind != shared::ENVIRONMENT_COLOR);
    return key.hash;
}

}  // namespace sdfwb::program
