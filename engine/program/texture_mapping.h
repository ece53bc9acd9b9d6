#pragma once
// How an image texture lands on a primitive (sdf/glsl/texture_mapping.glsl):
// the mapping code and the slots it reads, from the node's fields, and how
// fast (u, v) runs over the surface, for the mip level.

#include <glm/vec4.hpp>

#include "scene/scene.h"

namespace sdfwb::program {

struct TextureMapping {
    int mapping;  // MAP_*
    glm::dvec4 s0{0.0};
    glm::dvec4 s1{0.0};
    // The most (u, v) units one object unit of surface spans, in any
    // direction: an isotropic footprint errs towards blur, never aliasing.
    double uvPerUnit = 0.0;
};

// `tileSize` is the material's texture scale, the side of a plane's tiles.
// For the nine primitives with a parametrization (formulas are mapped
// triplanar instead); throws std::logic_error for any other kind.
TextureMapping textureMapping(const scene::Node& node, double tileSize);

}  // namespace sdfwb::program
