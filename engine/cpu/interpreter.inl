// The CPU backend's kernel, included once per precision inside a namespace that
// has `using namespace sdfwb::sdf::f32` (or f64) in effect. No include guard.

inline Material materialAtSlot(const vec4* params, int slot) {
    return materialFromSlots(params[slot], params[slot + 1], params[slot + 2], params[slot + 3]);
}

// Per-thread working memory of one program: register files and formula evaluators.
struct Scratch {
    std::vector<vec3> points;
    std::vector<Sample> samples;
    std::vector<expr::Evaluator<real>> formulas;

    explicit Scratch(const program::Program& program)
        : points(static_cast<size_t>(program.pointRegisters)), samples(static_cast<size_t>(program.sampleRegisters)) {
        for (const program::FormulaCode& formula : program.formulas) {
            formulas.emplace_back(formula.tape);
        }
    }

    // The formula's outputs at p: value, or value and gradient.
    std::span<const real> formula(int index, vec3 p) {
        const real xyz[3] = {p.x, p.y, p.z};
        return formulas[static_cast<size_t>(index)](std::span<const real>(xyz, 3));
    }
};

// The scene's distance field: runs the program's instructions on `point`.
inline Sample mapProgram(const program::Program& program, const vec4* params, Scratch& scratch, vec3 point) {
    using program::Opcode;
    vec3* points = scratch.points.data();
    Sample* samples = scratch.samples.data();
    points[0] = point;
    for (const program::Instruction& in : program.code) {
        const vec4* q = in.param >= 0 ? params + in.param : nullptr;
        vec3& p = points[in.a >= 0 ? in.a : 0];
        switch (in.op) {
        case Opcode::Translate: points[in.dst] = instTranslate(p, q[0]); break;
        case Opcode::Rotate: points[in.dst] = instRotate(p, q[0], q[1], q[2]); break;
        case Opcode::Scale: points[in.dst] = instScale(p, q[0]); break;
        case Opcode::Twist: points[in.dst] = instTwist(p, q[0]); break;
        case Opcode::Bend: points[in.dst] = instBend(p, q[0]); break;
        case Opcode::Elongate: points[in.dst] = instElongate(p, q[0]); break;
        case Opcode::Mirror: points[in.dst] = instMirror(p, q[0]); break;
        case Opcode::Repeat: points[in.dst] = instRepeat(p, q[0], q[1]); break;
        case Opcode::RepeatInfinite: points[in.dst] = instRepeatInfinite(p, q[0]); break;
        case Opcode::Sphere: samples[in.dst] = shapeSample(instSphere(p, q[0]), materialAtSlot(params, in.material)); break;
        case Opcode::Box: samples[in.dst] = shapeSample(instBox(p, q[0]), materialAtSlot(params, in.material)); break;
        case Opcode::RoundBox: samples[in.dst] = shapeSample(instRoundBox(p, q[0]), materialAtSlot(params, in.material)); break;
        case Opcode::Plane: samples[in.dst] = shapeSample(instPlane(p, q[0]), materialAtSlot(params, in.material)); break;
        case Opcode::Torus: samples[in.dst] = shapeSample(instTorus(p, q[0]), materialAtSlot(params, in.material)); break;
        case Opcode::Cone: samples[in.dst] = shapeSample(instCone(p, q[0]), materialAtSlot(params, in.material)); break;
        case Opcode::Ellipsoid: samples[in.dst] = shapeSample(instEllipsoid(p, q[0]), materialAtSlot(params, in.material)); break;
        case Opcode::Cylinder: samples[in.dst] = shapeSample(instCylinder(p, q[0]), materialAtSlot(params, in.material)); break;
        case Opcode::Capsule: samples[in.dst] = shapeSample(instCapsule(p, q[0], q[1]), materialAtSlot(params, in.material)); break;
        case Opcode::Ground: samples[in.dst] = instGround(p, q[0], q[1], q[2], materialAtSlot(params, in.material)); break;
        case Opcode::SdfFormula:
            samples[in.dst] = shapeSample(instSdfFormula(scratch.formula(in.variant, p)[0]), materialAtSlot(params, in.material));
            break;
        case Opcode::ImplicitFormula: {
            std::span<const real> v = scratch.formula(in.variant, p);
            samples[in.dst] = instImplicit(p, vec4(v[0], v[1], v[2], v[3]), q[0], q[1], materialAtSlot(params, in.material));
            break;
        }
        case Opcode::Union: samples[in.dst] = instUnion(samples[in.a], samples[in.b]); break;
        case Opcode::Intersection: samples[in.dst] = instIntersection(samples[in.a], samples[in.b]); break;
        case Opcode::Difference: samples[in.dst] = instDifference(samples[in.a], samples[in.b]); break;
        case Opcode::SmoothUnion: samples[in.dst] = instSmoothUnion(samples[in.a], samples[in.b], q[0], in.variant); break;
        case Opcode::SmoothIntersection:
            samples[in.dst] = instSmoothIntersection(samples[in.a], samples[in.b], q[0], in.variant);
            break;
        case Opcode::SmoothDifference:
            samples[in.dst] = instSmoothDifference(samples[in.a], samples[in.b], q[0], in.variant);
            break;
        case Opcode::ScaleDistance: samples[in.dst] = instScaleDistance(samples[in.a], points[in.b], q[0]); break;
        case Opcode::RoundDistance: samples[in.dst] = instRoundDistance(samples[in.a], points[in.b], q[0]); break;
        case Opcode::Displace: samples[in.dst] = instDisplace(samples[in.a], points[in.b], q[0]); break;
        case Opcode::StepScale: samples[in.dst] = instStepScale(samples[in.a], points[in.b], q[0]); break;
        case Opcode::Empty: samples[in.dst] = instEmpty(materialAtSlot(params, 0)); break;
        }
    }
    return samples[program.result];
}

struct SampleResult {
    vec3 color;
    int steps;
    bool hit;
    real t;  // march distance of the hit
};

// One sub-sample of one pixel, driven exactly as the GLSL backend's loop drives it.
inline SampleResult traceSample(const program::Program& program, const vec4* params, Scratch& scratch,
                                const Camera& camera, const TraceSettings& settings, const Light* lights, real px,
                                real py) {
    Ray ray = cameraRay(camera, px, py, real(program.width), real(program.height));
    TraceState s = traceBegin(ray);
    Sample field = shapeSample(real(0), s.material);
    Light noLight = Light(vec3(real(0), real(1), real(0)), vec3(real(0)), real(1));
    while (s.phase != PHASE_DONE) {
        Light light = settings.lightCount > 0 ? lights[lightIndex(s) < settings.lightCount ? lightIndex(s) : 0] : noLight;
        if (traceNeedsSample(s)) {
            field = mapProgram(program, params, scratch, tracePoint(s, light, settings));
        }
        s = traceAdvance(s, field, light, settings);
    }
    return SampleResult{s.color, s.steps, s.hit, s.t};
}

// The scene's constants converted to this precision once per render.
struct Kernel {
    using Real = real;
    using Vec3 = vec3;
    using ScratchType = Scratch;

    const program::Program& program;
    std::vector<vec4> params;
    Camera camera;
    TraceSettings settings;
    std::vector<Light> lights;

    explicit Kernel(const program::Program& p) : program(p) {
        for (const glm::dvec4& v : p.params) {
            params.push_back(vec4(v));
        }
        const program::CameraParams& c = p.camera;
        camera = Camera(vec3(c.origin), vec3(c.forward), vec3(c.right), vec3(c.up), real(c.tanHalfFov));
        const program::TraceParams& t = p.trace;
        settings = TraceSettings(t.maxSteps, real(t.maxDistance), real(t.epsilon), real(t.epsilonPerDistance),
                                 t.shadowMode, t.shadowSteps, t.aoSamples, real(t.aoDistance), t.lightingModel,
                                 real(t.stepRelaxation), static_cast<int>(p.lights.size()), vec3(t.ambientLight), vec3(t.background));
        for (const program::LightParams& l : p.lights) {
            lights.push_back(Light(vec3(l.direction), vec3(l.color), real(l.softness)));
        }
    }

    SampleResult trace(Scratch& scratch, real px, real py) const {
        return traceSample(program, params.data(), scratch, camera, settings, lights.data(), px, py);
    }

    Sample map(Scratch& scratch, vec3 p) const { return mapProgram(program, params.data(), scratch, p); }

    static real offset(int index, int aa) { return subsampleOffset(index, aa); }
};
