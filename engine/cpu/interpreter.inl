// The CPU backend's kernel, included once per precision by cpu/interpreter.h
// inside a namespace that has `using namespace sdfwb::sdf::f32` (or f64) in
// effect. No include guard.

inline Material materialAtSlot(const vec4* params, int slot) {
    return materialFromSlots(params[slot], params[slot + 1], params[slot + 2], params[slot + 3], params[slot + 4],
                             params[slot + 5]);
}

// A sample register of an evaluation that reads distances only.
struct Distances {
    real d;
    real step;
};

// Per-thread working memory of one program: register files and formula evaluators.
struct Scratch {
    std::vector<vec3> points;
    std::vector<Sample> samples;
    std::vector<Distances> distances;
    std::vector<expr::Evaluator<real>> formulas;

    explicit Scratch(const program::Program& program)
        : points(static_cast<size_t>(program.pointRegisters)),
          samples(static_cast<size_t>(program.sampleRegisters)),
          distances(static_cast<size_t>(program.sampleRegisters)) {
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

// Calls f(q[0], ..., q[Slots - 1]): an instruction's parameter slots as arguments.
template <int Slots, typename F>
inline auto withSlots(const vec4* q, F f) {
    return [&]<size_t... I>(std::index_sequence<I...>) { return f(q[I]...); }(std::make_index_sequence<Slots>{});
}

// The texel buffer of the scene's images (program/scene_images.h) as the
// shared samplers read it, T(i): the environment's texels, then the
// textures'. Out of range (a NaN coordinate's texel) reads zero, as
// texelFetch does.
struct Texels {
    const program::ResolvedImages* images = nullptr;  // null: no images (picking, point queries)
    real textureStretch = real(1);  // the footprint factor of image textures, 0: no colour needed (sample_driver.glsl)
    vec4 footprintShift = vec4(real(0));  // footprint_point.glsl's, set by the driver; w = 0: none

    vec4 T(int i) const {
        if (images == nullptr || i < 0) return vec4(real(0));
        auto index = static_cast<size_t>(i);
        if (images->environment) {
            if (index < images->environment->texels.size()) return vec4(images->environment->texels[index]);
            index -= images->environment->texels.size();
        }
        for (const auto& texture : images->textures) {
            if (index < texture->texels.size()) return vec4(texture->texels[index]);
            index -= texture->texels.size();
        }
        return vec4(real(0));
    }

#include "sdf/glsl/footprint_point.glsl"
#include "sdf/glsl/mipmap_lookup.glsl"
#include "sdf/glsl/texture_lookup.glsl"
};

// The ImageTexture opcode's function as the opcode table names it, with the
// texel buffer it reads as its first argument (GLSL reads a global).
template <typename... Args>
inline Sample instImageTexture(Texels texels, Args... args) {
    return texels.instImageTexture(args...);
}
template <typename... Args>
inline Sample instTriplanarTexture(Texels texels, Args... args) {
    return texels.instTriplanarTexture(args...);
}

// The sample registers of an evaluation that carries materials.
struct MaterialSamples {
    Sample* registers;
    const vec4* params;

    Sample get(int i) const { return registers[i]; }
    void set(int i, Sample s) const { registers[i] = s; }
    Material material(int slot) const { return materialAtSlot(params, slot); }
};

// The sample registers of an evaluation that reads distances only
// (traceMaterialReads): the same shared functions run on samples whose
// material is a constant, and with nothing storing the materials they
// compute, the compiler drops that work (loads, mixes, ground patterns).
// Image textures skip their lookups at stretch 0 anyway; a triplanar
// texture's formula still runs (its tape is not free of side effects).
struct DistanceSamples {
    Distances* registers;

    Sample get(int i) const { return Sample(registers[i].d, registers[i].step, noMaterial()); }
    void set(int i, Sample s) const { registers[i] = Distances{s.d, s.step}; }
    Material material(int) const { return noMaterial(); }
};

// The register files and constants one instruction reads.
template <typename Samples>
struct Registers {
    vec3* points;
    Samples samples;
    Scratch& scratch;
    Texels texels;  // a copy: the shared functions are not const members
    vec3 footprint;  // the point footprints are measured from, footprintPoint(P[0])
};

// One function per operand class (program/opcodes.h), so each opcode's wiring
// follows from its class in the opcode table, as the GLSL generator's does.
template <int Slots, typename F, typename R>
inline void runPoint(F fn, const program::Instruction& in, const vec4* q, R& r) {
    r.points[in.dst] = withSlots<Slots>(q, [&](auto... s) { return fn(r.points[in.a], s...); });
}
template <int Slots, typename F, typename R>
inline void runShape(F fn, const program::Instruction& in, const vec4* q, R& r) {
    real d = withSlots<Slots>(q, [&](auto... s) { return fn(r.points[in.a], s...); });
    r.samples.set(in.dst, shapeSample(d, r.samples.material(in.material)));
}
template <int Slots, typename F, typename R>
inline void runShapeSample(F fn, const program::Instruction& in, const vec4* q, R& r) {
    r.samples.set(in.dst, withSlots<Slots>(q, [&](auto... s) {
                      return fn(r.points[in.a], r.footprint, s..., r.samples.material(in.material));
                  }));
}
template <int Slots, typename F, typename R>
inline void runFormulaShape(F fn, const program::Instruction& in, const vec4*, R& r) {
    static_assert(Slots == 0, "a formula shape reads only its formula");
    r.samples.set(in.dst,
                  shapeSample(fn(r.scratch.formula(in.variant, r.points[in.a])[0]), r.samples.material(in.material)));
}
template <int Slots, typename F, typename R>
inline void runFormulaSample(F fn, const program::Instruction& in, const vec4* q, R& r) {
    std::span<const real> v = r.scratch.formula(in.variant, r.points[in.a]);
    vec4 value(v[0], v[1], v[2], v[3]);
    r.samples.set(in.dst, withSlots<Slots>(q, [&](auto... s) {
                      return fn(r.points[in.a], value, s..., r.samples.material(in.material));
                  }));
}
template <int Slots, typename F, typename R>
inline void runCombine(F fn, const program::Instruction& in, const vec4*, R& r) {
    static_assert(Slots == 0, "a hard boolean has no parameters");
    r.samples.set(in.dst, fn(r.samples.get(in.a), r.samples.get(in.b)));
}
template <int Slots, typename F, typename R>
inline void runSmoothCombine(F fn, const program::Instruction& in, const vec4* q, R& r) {
    r.samples.set(in.dst, withSlots<Slots>(q, [&](auto... s) {
                      return fn(r.samples.get(in.a), r.samples.get(in.b), s..., in.variant);
                  }));
}
template <int Slots, typename F, typename R>
inline void runPost(F fn, const program::Instruction& in, const vec4* q, R& r) {
    r.samples.set(in.dst,
                  withSlots<Slots>(q, [&](auto... s) { return fn(r.samples.get(in.a), r.points[in.b], s...); }));
}
template <int Slots, typename F, typename R>
inline void runTexture(F fn, const program::Instruction& in, const vec4* q, R& r) {
    r.samples.set(in.dst, withSlots<Slots>(q, [&](auto... s) {
                      return fn(r.samples.get(in.a), r.points[in.b], r.footprint, s...);
                  }));
}
template <int Slots, typename F, typename R>
inline void runImageTexture(F fn, const program::Instruction& in, const vec4* q, R& r) {
    r.samples.set(in.dst, withSlots<Slots>(q, [&](auto... s) {
                      return fn(r.texels, r.samples.get(in.a), r.points[in.b], r.footprint, s...);
                  }));
}
template <int Slots, typename F, typename R>
inline void runFormulaImageTexture(F fn, const program::Instruction& in, const vec4* q, R& r) {
    std::span<const real> v = r.scratch.formula(in.variant, r.points[in.b]);
    vec4 value(v[0], v[1], v[2], v[3]);
    r.samples.set(in.dst, withSlots<Slots>(q, [&](auto... s) {
                      return fn(r.texels, r.samples.get(in.a), r.points[in.b], r.footprint, value, s...);
                  }));
}
template <int Slots, typename F, typename R>
inline void runConstant(F fn, const program::Instruction& in, const vec4*, R& r) {
    r.samples.set(in.dst, fn(r.samples.material(MATERIAL_SLOT)));
}

// Runs `code` (the program's instructions, or a pruned list of them) on
// `point` into the sample registers `samples` and returns register `result`.
// The switch is expanded from the opcode table, one case per opcode.
template <typename Samples>
inline Sample runCodeOn(Samples samples, std::span<const program::Instruction> code, int result, const vec4* params,
                        Scratch& scratch, vec3 point, const Texels& texels) {
    Registers<Samples> r{scratch.points.data(), samples, scratch, texels, vec3(real(0))};
    r.points[0] = point;
    r.footprint = r.texels.footprintPoint(point);
    for (const program::Instruction& in : code) {
        const vec4* q = in.param >= 0 ? params + in.param : nullptr;
        switch (in.op) {
#define SDFWB_OPCODE_CASE(op, name, cls, slots, fn)                                   \
    case program::Opcode::op:                                                         \
        run##cls<slots>([](auto... args) { return fn(args...); }, in, q, r);          \
        break;
            SDFWB_OPCODES(SDFWB_OPCODE_CASE)
#undef SDFWB_OPCODE_CASE
        }
    }
    return r.samples.get(result);
}

// `code` on `point`, with materials, or read for its distances only: then
// the sample's material is noMaterial().
inline Sample runCode(std::span<const program::Instruction> code, int result, const vec4* params, Scratch& scratch,
                      vec3 point, const Texels& texels = Texels{}, bool withMaterial = true) {
    if (withMaterial) {
        return runCodeOn(MaterialSamples{scratch.samples.data(), params}, code, result, params, scratch, point, texels);
    }
    return runCodeOn(DistanceSamples{scratch.distances.data()}, code, result, params, scratch, point, texels);
}

// The scene's distance field: runs the program's instructions on `point`.
inline Sample mapProgram(const program::Program& program, const vec4* params, Scratch& scratch, vec3 point) {
    return runCode(program.code, program.result, params, scratch, point);
}

// The field at `point`: the pruned instructions of the point's cell when the
// program has a grid (engine/prune), else the whole program.
inline Sample fieldAt(const program::Program& program, const prune::PruneGrid* grid, const vec4* params,
                      Scratch& scratch, vec3 point, const Texels& texels = Texels{}, bool withMaterial = true) {
    if (grid == nullptr) {
        return runCode(program.code, program.result, params, scratch, point, texels, withMaterial);
    }
    const prune::PruneLeaf& leaf = grid->leaves[static_cast<size_t>(prune::leafIndexAt(*grid, point))];
    std::span<const program::Instruction> code(grid->code.data() + leaf.offset, static_cast<size_t>(leaf.count));
    return runCode(code, leaf.result, params, scratch, point, texels, withMaterial);
}

struct SampleResult {
    vec3 color;
    int steps;
    int evaluations;
    bool hit;
    real t;  // march distance of the hit
};

// The shared driver loop (sdf/glsl/sample_driver.glsl) with this backend's
// P(slot) and map(p), as the generated shader has them.
struct SampleDriver : Texels {
    const program::Program& program;
    const prune::PruneGrid* grid;
    const vec4* params;
    Scratch& scratch;
    bool distanceOnlyAllowed;  // Program::distanceOnlyEvaluation, the debug switch
    int sceneMaterialReads;    // the fields worth a material (Program::materialReads)
    bool materialApart;        // Program::materialPhaseApart
    bool withMaterial = true;

    vec4 P(int slot) const { return params[slot]; }
    Sample map(vec3 p) { return fieldAt(program, grid, params, scratch, p, *this, withMaterial); }
    // setMaterialReads has decided what map() carries
    Sample mapDistance(vec3 p) { return map(p); }
    Sample mapMaterial(vec3 p) { return map(p); }
    bool materialSampledApart() const { return materialApart; }
    bool secondaryRays() const { return program.secondaryRays; }
    bool environmentMap() const { return images != nullptr && images->environment != nullptr; }
    bool imageTextures() const { return !program.textureFiles.empty(); }
    int materialSamplesPerHit() const { return program.materialSamplesPerHit(); }
    void setTextureStretch(real k) { textureStretch = k; }
    void setFootprintShift(vec4 shift) { footprintShift = shift; }
    void setMaterialReads(int reads) { withMaterial = !distanceOnlyAllowed || (reads & sceneMaterialReads) != 0; }

#include "sdf/glsl/environment_lookup.glsl"
#include "sdf/glsl/sample_driver.glsl"
};

// Where a kernel's field comes from. Both give the same floats (a pruned leaf
// equals the whole program in its cell); a grid costs seconds to build on a
// large scene and pays back only over many rays, so single rays and point
// queries (picking, placement, the readout, on the UI thread) take the whole.
// Those also see the background colour instead of an environment map's
// images and black for image textures: the images would have to be read
// from disk first. PrunedIfBuilt takes the grid when it is built and the
// whole program otherwise, starting the grid's build in the background.
enum class FieldSource { Pruned, PrunedIfBuilt, Whole };

// The scene's constants converted to this precision once per render.
struct Kernel {
    using Real = real;
    using Vec3 = vec3;
    using ScratchType = Scratch;
    using SourceType = FieldSource;

    const program::Program& program;
    std::shared_ptr<const prune::PruneGrid> grid;
    std::vector<vec4> params;  // the program's, then the grid's
    program::ResolvedImages images;
    // The material fields of this scene the tracer's evaluations read
    // (Program::materialReads): an evaluation that reads none of them
    // leaves the materials out.
    int materialReads;
    bool materialApart;  // Program::materialPhaseApart, computed once

    explicit Kernel(const program::Program& p, FieldSource source = FieldSource::Pruned)
        : program(p),
          grid(gridFrom(p, source)),
          materialReads(p.materialReads()),
          materialApart(p.materialPhaseApart()) {
        for (const glm::dvec4& v : p.params) {
            params.push_back(vec4(v));
        }
        if (source != FieldSource::Whole) {
            images = program::resolveImages(p);
            for (const auto& [slot, value] : images.slots) params[static_cast<size_t>(slot)] = vec4(value);
        }
        if (grid) {
            for (const glm::dvec4& v : grid->extraParams) {
                params.push_back(vec4(v));
            }
        }
    }

    static std::shared_ptr<const prune::PruneGrid> gridFrom(const program::Program& p, FieldSource source) {
        switch (source) {
        case FieldSource::Pruned: return prune::pruneGridFor(p);
        case FieldSource::PrunedIfBuilt: return prune::pruneGridIfBuilt(p).value_or(nullptr);
        case FieldSource::Whole: return nullptr;
        }
        return nullptr;
    }

    // The primary ray through (px, py), from the camera block of the parameters.
    Ray ray(real px, real py) const {
        Camera camera = cameraFromSlots(params[CAMERA_SLOT], params[CAMERA_SLOT + 1], params[CAMERA_SLOT + 2],
                                        params[CAMERA_SLOT + 3]);
        return cameraRay(camera, px, py, real(program.width), real(program.height));
    }

    SampleResult trace(Scratch& scratch, real px, real py) const {
        bool distanceOnly = program.distanceOnlyEvaluation;
        SampleDriver driver{{&images}, program, grid.get(), params.data(), scratch, distanceOnly, materialReads,
                            materialApart};
        TraceState s = driver.traceSample(px, py, real(program.width), real(program.height));
        return SampleResult{s.color, s.steps, s.evaluations, s.hit, s.t};
    }

    Sample map(Scratch& scratch, vec3 p) const { return mapProgram(program, params.data(), scratch, p); }

    static real offset(int index, int aa) { return subsampleOffset(index, aa); }
};
