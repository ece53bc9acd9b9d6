#pragma once
// The key both caches of the tradeoff command file their entries under
// (references, and the measurements taken against them): a hash of what an
// entry depends on, so a change to the scene, to the shared shading code or
// to the renderer's version finds no stale entry.

#include <string>
#include <string_view>

#include "scene/scene.h"

namespace sdfwb::tradeoff {

// 16 hex digits over the renderer's version, `shadingCode` and `keyed`
// (serialized as the scene format writes it; the caller strips what the
// entry does not depend on).
std::string cacheKey(const scene::Scene& keyed, std::string_view shadingCode);

}  // namespace sdfwb::tradeoff
