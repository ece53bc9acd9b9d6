#include "program/compile_scene.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "program/bounds.h"
#include "expr/derivative.h"
#include "expr/formula.h"
#include "program/rotation.h"
#include "scene/camera_frame.h"

namespace sdfwb::program {

using glm::dvec3;
using glm::dvec4;
using scene::Node;
using scene::NodeKind;

namespace {

// Codes shared with the tracer and operators of the shared library.
constexpr int kSmoothVariantCodes = 4;  // polynomial, exponential, power, root: SMOOTH_* in operators.glsl

// Twist and bend stretch space: the field's Lipschitz constant grows to about
// sqrt(1 + (k r)^2) at radius r from the axis. Steps are scaled by its inverse
// over the child's bounds, never below this floor (an unbounded child).
constexpr double kMinStepFactor = 0.05;

class Compiler {
public:
    explicit Compiler(const scene::Scene& scene) : scene_(scene) {
        defaultMaterialSlot_ = addMaterial(scene::defaultMaterial());
        for (const scene::Material& m : scene.materials) {
            materialSlots_[m.name] = addMaterial(m);
        }
    }

    Program& program() { return program_; }

    // Compiles `node` evaluated at P[point] + offset; returns the sample register.
    int compile(const Node& node, int point, dvec3 offset) {
        switch (kindSpec(node.kind).category) {
        case scene::NodeCategory::Primitive: return compilePrimitive(node, point, offset);
        case scene::NodeCategory::Boolean: return compileBoolean(node, point, offset);
        default: return compileUnary(node, point, offset);
        }
    }

    int compileGround(const scene::Ground& ground, const dvec3& eye) {
        int s = allocSample();
        int param = addParams({dvec4(ground.height - eye.y, static_cast<double>(ground.pattern), 0, 0),
                               dvec4(eye, ground.cellSize), dvec4(ground.secondColor, ground.lineWidth)});
        emit({Opcode::Ground, s, 0, -1, param, materialSlot(ground.material), 0});
        return s;
    }

    void combine(Opcode op, int accumulator, int other, int param, int variant) {
        emit({op, accumulator, accumulator, other, param, -1, variant});
        releaseSample();
    }

private:
    int addParams(std::initializer_list<dvec4> values) {
        int first = static_cast<int>(program_.params.size());
        program_.params.insert(program_.params.end(), values.begin(), values.end());
        return first;
    }

    int addMaterial(const scene::Material& m) {
        return addParams({dvec4(m.ambient, m.shininess), dvec4(m.diffuse, 0), dvec4(m.specular, 0),
                          dvec4(m.emission, 0)});
    }

    // The formula's tape: value, or value and gradient (x, y, z are variables 0, 1, 2).
    int addFormula(const std::string& source, bool withGradient) {
        expr::SpaceFormula formula = withGradient ? expr::compileImplicit(source) : expr::compileSdf(source);
        std::vector<expr::NodeId> outputs = {formula.value};
        if (withGradient) {
            std::array<expr::NodeId, 3> gradient = expr::gradient(formula.graph, formula.value);
            outputs.insert(outputs.end(), gradient.begin(), gradient.end());
        }
        program_.formulas.push_back({source, withGradient, expr::Tape(formula.graph, outputs)});
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

    int compilePrimitive(const Node& node, int point, dvec3 offset) {
        int p = materialize(point, offset);
        int s = allocSample();
        int material = materialSlot(node.text("material"));
        auto shape = [&](Opcode op, std::initializer_list<dvec4> params) {
            emit({op, s, p, -1, addParams(params), material, 0});
        };
        switch (node.kind) {
        case NodeKind::Sphere: shape(Opcode::Sphere, {dvec4(node.real("radius"), 0, 0, 0)}); break;
        case NodeKind::Box: shape(Opcode::Box, {dvec4(node.vec3("half_extents"), 0)}); break;
        case NodeKind::RoundBox: {
            dvec3 h = node.vec3("half_extents");
            double r = std::min(node.real("radius"), std::min(h.x, std::min(h.y, h.z)));
            shape(Opcode::RoundBox, {dvec4(h, r)});
            break;
        }
        case NodeKind::Plane:
            shape(Opcode::Plane, {dvec4(glm::normalize(node.vec3("normal")), node.real("offset"))});
            break;
        case NodeKind::Torus:
            shape(Opcode::Torus, {dvec4(node.real("major_radius"), node.real("minor_radius"), 0, 0)});
            break;
        case NodeKind::Cone: {
            double angle = node.real("angle") * M_PI / 180.0;
            shape(Opcode::Cone, {dvec4(std::sin(angle), std::cos(angle), node.real("height"), 0)});
            break;
        }
        case NodeKind::Ellipsoid: shape(Opcode::Ellipsoid, {dvec4(node.vec3("radii"), 0)}); break;
        case NodeKind::Cylinder:
            shape(Opcode::Cylinder, {dvec4(node.real("radius"), node.real("half_height"), 0, 0)});
            break;
        case NodeKind::Capsule:
            shape(Opcode::Capsule, {dvec4(node.vec3("a"), node.real("radius")), dvec4(node.vec3("b"), 0)});
            break;
        case NodeKind::Sdf:
            emit({Opcode::SdfFormula, s, p, -1, -1, material, addFormula(node.text("formula"), false)});
            break;
        case NodeKind::Implicit:
        case NodeKind::Polynomial: {
            dvec3 lo = node.vec3("bounds_min"), hi = node.vec3("bounds_max");
            emit({Opcode::ImplicitFormula, s, p, -1,
                  addParams({dvec4((lo + hi) * 0.5, node.real("max_step")),
                             dvec4((hi - lo) * 0.5, node.real("sheet_thickness") * 0.5)}),
                  material,
                  addFormula(node.text("formula"), true)});
            break;
        }
        default: break;
        }
        if (p != point) {
            releasePoint();
        }
        return s;
    }

    int compileBoolean(const Node& node, int point, dvec3 offset) {
        if (node.children.empty()) {
            int s = allocSample();
            emit({Opcode::Empty, s, -1, -1, -1, -1, 0});
            return s;
        }
        int accumulator = compile(node.children[0], point, offset);
        Opcode op = Opcode::Union;
        int variant = 0;
        bool smooth = false;
        switch (node.kind) {
        case NodeKind::Union: op = Opcode::Union; break;
        case NodeKind::Intersection: op = Opcode::Intersection; break;
        case NodeKind::Difference: op = Opcode::Difference; break;
        case NodeKind::SmoothUnion: op = Opcode::SmoothUnion; smooth = true; break;
        case NodeKind::SmoothIntersection: op = Opcode::SmoothIntersection; smooth = true; break;
        case NodeKind::SmoothDifference: op = Opcode::SmoothDifference; smooth = true; break;
        default: break;
        }
        int param = -1;
        if (smooth) {
            const auto& choices = kindSpec(node.kind).fields[static_cast<size_t>(fieldIndex(kindSpec(node.kind), "variant"))].choices;
            variant = static_cast<int>(std::find(choices.begin(), choices.end(), node.text("variant")) - choices.begin());
            variant = std::clamp(variant, 0, kSmoothVariantCodes - 1);
            param = addParams({dvec4(node.real("k"), node.real("exponent"), 0, 0)});
        }
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

    int compileUnary(const Node& node, int point, dvec3 offset) {
        const Node& child = node.children.at(0);
        switch (node.kind) {
        case NodeKind::Translate: return compile(child, point, offset - node.vec3("offset"));
        case NodeKind::Rotate: {
            glm::dmat3 inverse = glm::transpose(rotationFromAngles(node.vec3("angles")));
            // rows of the inverse rotation
            int r = pointOp(Opcode::Rotate, point,
                            {dvec4(inverse[0][0], inverse[1][0], inverse[2][0], 0),
                             dvec4(inverse[0][1], inverse[1][1], inverse[2][1], 0),
                             dvec4(inverse[0][2], inverse[1][2], inverse[2][2], 0)});
            int s = compile(child, r, inverse * offset);
            releasePoint();
            return s;
        }
        case NodeKind::Scale: {
            double factor = node.real("factor");
            int r = pointOp(Opcode::Scale, point, {dvec4(factor, 0, 0, 0)});
            int s = compile(child, r, offset / factor);
            releasePoint();
            postOp(Opcode::ScaleDistance, s, r, {dvec4(factor, 0, 0, 0)});
            return s;
        }
        case NodeKind::Round: {
            int s = compile(child, point, offset);
            postOp(Opcode::RoundDistance, s, point, {dvec4(node.real("radius"), 0, 0, 0)});
            return s;
        }
        case NodeKind::Displace: {
            int p = materialize(point, offset);
            int s = compile(child, p, dvec3(0.0));
            double amplitude = node.real("amplitude"), frequency = node.real("frequency");
            // |grad pattern| <= |a f| sqrt(3): scale steps so the field stays 1-Lipschitz
            double factor = 1.0 / (1.0 + std::abs(amplitude * frequency) * std::sqrt(3.0));
            postOp(Opcode::Displace, s, p, {dvec4(amplitude, frequency, factor, 0)});
            if (p != point) releasePoint();
            return s;
        }
        default: break;
        }

        int p = materialize(point, offset);
        int r = -1;
        double factor = 1.0;
        switch (node.kind) {
        case NodeKind::Twist: {
            double k = node.real("k");
            r = pointOp(Opcode::Twist, p, {dvec4(k, 0, 0, 0)});
            Bounds b = nodeBounds(child);
            factor = stepFactor(k, b.infinite ? INFINITY : b.radiusAboutY());
            break;
        }
        case NodeKind::Bend: {
            double k = node.real("k");
            r = pointOp(Opcode::Bend, p, {dvec4(k, 0, 0, 0)});
            Bounds b = nodeBounds(child);
            factor = stepFactor(k, b.infinite ? INFINITY : b.radiusAboutZ());
            break;
        }
        case NodeKind::Elongate: r = pointOp(Opcode::Elongate, p, {dvec4(node.vec3("h"), 0)}); break;
        case NodeKind::Mirror: {
            const std::string& axes = node.text("axes");
            dvec3 mask(axes.find('x') != std::string::npos, axes.find('y') != std::string::npos,
                       axes.find('z') != std::string::npos);
            r = pointOp(Opcode::Mirror, p, {dvec4(mask, 0)});
            break;
        }
        case NodeKind::Repeat:
            r = pointOp(Opcode::Repeat, p, {dvec4(node.vec3("spacing"), 0), dvec4(node.vec3("counts"), 0)});
            break;
        case NodeKind::RepeatInfinite: r = pointOp(Opcode::RepeatInfinite, p, {dvec4(node.vec3("period"), 0)}); break;
        default: break;
        }
        int s = compile(child, r, dvec3(0.0));
        releasePoint();
        if (p != point) releasePoint();
        if (factor < 1.0) {
            postOp(Opcode::StepScale, s, point, {dvec4(factor, 0, 0, 0)});
        }
        return s;
    }

    const scene::Scene& scene_;
    Program program_;
    std::map<std::string, int> materialSlots_;
    int defaultMaterialSlot_ = 0;
    int pointTop_ = 1;
    int sampleTop_ = 0;
};

}  // namespace

Program compileScene(const scene::Scene& scene, const CompileOptions& options) {
    Compiler compiler(scene);
    scene::CameraFrame frame = scene::cameraFrame(scene.camera);
    int result = compiler.compile(scene.root, 0, frame.eye);
    if (scene.environment.ground.enabled) {
        int ground = compiler.compileGround(scene.environment.ground, frame.eye);
        compiler.combine(Opcode::Union, result, ground, -1, 0);
    }
    Program program = std::move(compiler.program());
    program.result = result;

    const scene::RenderSettings& r = scene.render;
    program.width = options.width > 0 ? options.width : r.width;
    program.height = options.height > 0 ? options.height : r.height;
    program.aa = options.aa > 0 ? options.aa : r.aa;
    program.camera = {dvec3(0.0), frame.forward, frame.right, frame.up, frame.tanHalfFov};

    TraceParams& t = program.trace;
    t.maxSteps = r.maxSteps;
    t.maxDistance = r.maxDistance;
    if (r.epsilonMode == scene::EpsilonMode::Pixel) {
        // r.epsilon sub-sample footprints: at distance t one sub-sample spans
        // t * 2 tan(fov/2) / (height * aa), so higher AA also resolves finer detail
        // instead of averaging silhouettes dilated by a whole pixel's epsilon
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
    t.ambientLight = scene.environment.ambient;
    t.background = scene.environment.background;
    for (const scene::Light& light : scene.lights) {
        program.lights.push_back({glm::normalize(light.direction), light.color, light.softness});
    }
    return program;
}

std::uint64_t Program::structureKey() const {
    std::uint64_t hash = 1469598103934665603ull;
    auto mix = [&](std::int64_t value) {
        for (int i = 0; i < 8; ++i) {
            hash ^= static_cast<std::uint64_t>(value >> (8 * i)) & 0xffu;
            hash *= 1099511628211ull;
        }
    };
    for (const Instruction& in : code) {
        mix(static_cast<int>(in.op));
        mix(in.dst);
        mix(in.a);
        mix(in.b);
        mix(in.param);
        mix(in.material);
        mix(in.variant);
    }
    mix(pointRegisters);
    mix(sampleRegisters);
    mix(result);
    for (const FormulaCode& formula : formulas) {
        mix(formula.withGradient);
        for (char c : formula.source) mix(c);
    }
    return hash;
}

}  // namespace sdfwb::program
