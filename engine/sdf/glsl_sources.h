#pragma once
// The shared SDF library as GLSL text, embedded at build time from sdf/glsl/*.glsl.

#include <string>
#include <string_view>

namespace sdfwb::sdf {

// GLSL 3.30 prelude that makes the shared subset compile: `real`, SHARED_FN,
// and the library's sin and cos (librarySin, libraryCos: see shared_instance.inl).
std::string_view glslPrelude();

// The shared sources in dependency order (math, transcendental, primitives,
// operators, material, camera, instructions, parameter blocks, tracer, ray
// tree, prune grid layout), concatenated.
std::string_view glslLibrary();

// The per-sample driver loop (sdf/glsl/sample_driver.glsl), pasted after the
// generated map() and P() it calls.
std::string_view glslSampleDriver();

// The footprint point, the mipmap sampler and the image textures that use it
// (sdf/glsl/footprint_point.glsl, mipmap_lookup.glsl, texture_lookup.glsl),
// pasted after the backend's texel accessor T(i) and footprint globals
// (textureStretch, footprintShift) and before the generated map() that calls them.
std::string_view glslTextureLookup();

// The environment map's sampler (sdf/glsl/environment_lookup.glsl), pasted
// after the texture lookup and before the driver.
std::string_view glslEnvironmentLookup();

// The prune grid's cell lookup (sdf/glsl/prune_lookup.glsl), pasted after the
// backend's node accessor PN(i).
std::string_view glslPruneLookup();

// Every piece above in one text: what the shading the backends run depends
// on (the reference cache keys on it).
std::string sharedShadingCode();

}  // namespace sdfwb::sdf
