#include "tradeoff/cache_key.h"

#include <cstdint>
#include <cstdio>

#include "scene/scene_json.h"

namespace sdfwb::tradeoff {
namespace {

// The shading code is in the key itself (every sdf/glsl/ text); bump this for
// a change to the output made in C++ only (cpu/interpreter.inl, program/,
// expr/, the reference's settings).
constexpr std::string_view kRendererVersion = "sdfwb-reference-2";

}  // namespace

std::string cacheKey(const scene::Scene& keyed, std::string_view shadingCode) {
    std::string text =
        std::string(kRendererVersion) + "\n" + std::string(shadingCode) + "\n" + scene::serializeScene(keyed);
    std::uint64_t hash = 1469598103934665603ull;  // FNV-1a
    for (unsigned char c : text) {
        hash ^= c;
        hash *= 1099511628211ull;
    }
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(hash));
    return hex;
}

}  // namespace sdfwb::tradeoff
