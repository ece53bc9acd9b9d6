#pragma once
// Generates the fragment shader for a compiled scene: the shared SDF library,
// a straight-line map() with exactly the scene's instructions (a run of many
// children as one loop over a prune-grid cell's kept ones, gl/fold_run.h; parameters read
// from a buffer texture, so edits change data, not text), and one loop that
// drives the shared tracer with a single call site of map().

#include <string>

#include "program/program.h"

namespace sdfwb::gl {

// The GLSL 3.30 vertex shader drawing one full-screen triangle.
std::string_view vertexShaderSource();

// The parameter buffer's sampler uParams and its accessors P(slot) and
// M(slot) (a material's four slots), which map() reads; after the shared library.
std::string_view parameterAccessSource();

// The scene images' texel accessor T(i) (the uTexels buffer, or zero when
// `texels` is false), the footprint globals the driver sets (the image
// textures' factor, the footprint point's shift) and the shared footprint
// point and texture lookup, which map() calls; after parameterAccessSource().
std::string textureAccessSource(bool texels);

// The program's formulas, its map(vec3 p): straight-line code over its
// instructions (a fold run's as a loop), and the driver's mapDistance and
// mapMaterial (sample_driver.glsl): where materialSampledApart(program)
// (gl/program_size.h), the same code returning no material and map(); else
// map() and a stub the driver never calls. After the shared library and
// parameterAccessSource().
std::string generateMapFunction(const program::Program& program);

// The preprocessor lines that make the shared library compile only the smooth
// variants the program's smooth booleans use (operators.glsl, smoothMin);
// between glslPrelude() and glslLibrary().
std::string smoothVariantDefines(const program::Program& program);

// The fragment shader for `program`; depends only on its structure
// (program.structureKey()), never on parameter values.
std::string generateFragmentShader(const program::Program& program);

// llvmpipe stops any fragment invocation after 65535 loop back-edges and then
// continues silently with wrong values (docs/toolchain-notes.md). One pass runs
// at most traceIterationBound() iterations of the driver's loops (plus the
// outer loop's, where the material is sampled apart), so this is the pass's
// worst case outside map(); a fold loop in map() multiplies it
// (gl_renderer.cpp). It must stay below the limit.
inline constexpr int kLoopLimiter = 65535;
int worstCaseBackEdges(const program::Program& program);

}  // namespace sdfwb::gl
