#pragma once
// A compiled program and the double-precision CPU kernel over it, tracing one
// sub-sample at a time, with its trace settings read and rewritten through
// the parameter block's own unpacker and packer (parameter_blocks.glsl): the
// tracer tests compare what one ray does under settings the scene format
// does not offer (half of the bounded tracing, for instance).

#include "cpu/interpreter.h"
#include "program/compile_scene.h"
#include "scene/scene.h"

namespace sdfwb::test {

struct TracedProgram {
    explicit TracedProgram(const program::Program& p) : program(p), kernel(program), scratch(program) {}
    TracedProgram(const scene::Scene& s, int width, int height)
        : TracedProgram(program::compileScene(s, {width, height, 1})) {}

    cpu::f64::SampleResult at(int x, int y) { return kernel.trace(scratch, x + 0.5, y + 0.5); }
    cpu::f64::Ray ray(int x, int y) const { return kernel.ray(x + 0.5, y + 0.5); }

    program::Program program;
    cpu::f64::Kernel kernel;
    cpu::f64::Scratch scratch;
};

inline cpu::f64::TraceSettings traceSettingsOf(const program::Program& program) {
    const glm::dvec4* q = program.params.data() + cpu::f64::TRACE_SLOT;
    return cpu::f64::traceSettingsFromSlots(q[0], q[1], q[2], q[3], q[4], q[5], q[6]);
}

// The program with the bounds put to the uses `boundsUse` (BOUNDS_* bits) only.
inline program::Program withBoundsUse(program::Program program, int boundsUse) {
    cpu::f64::TraceSettings settings = traceSettingsOf(program);
    settings.boundsUse = boundsUse;
    for (int i = 0; i < cpu::f64::TRACE_SLOTS; ++i) {
        program.params[static_cast<size_t>(cpu::f64::TRACE_SLOT + i)] = cpu::f64::traceSettingsSlot(settings, i);
    }
    return program;
}

}  // namespace sdfwb::test
