#pragma once
// The shared SDF library as C++: the same .glsl sources the GLSL backend pastes
// into its shaders, compiled over GLM twice, with real = float (namespace
// sdfwb::sdf::f32, bit-compatible with the GLSL backend) and real = double
// (namespace sdfwb::sdf::f64, the reference). See docs/shared-glsl-subset.md.

#include <cmath>

#include <glm/glm.hpp>

// Marks every function of the shared sources; empty in GLSL, `inline` here so the
// definitions can live in a header.
#define SHARED_FN inline

namespace sdfwb::sdf {

#define SDFWB_SHARED_NS f32
#define SDFWB_SHARED_REAL float
#include "sdf/shared_instance.inl"
#undef SDFWB_SHARED_NS
#undef SDFWB_SHARED_REAL

#define SDFWB_SHARED_NS f64
#define SDFWB_SHARED_REAL double
#include "sdf/shared_instance.inl"
#undef SDFWB_SHARED_NS
#undef SDFWB_SHARED_REAL

}  // namespace sdfwb::sdf
