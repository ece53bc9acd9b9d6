#pragma once
// The reference a sweep measures error against: the double-precision CPU render
// of the scene with tight settings, cached on disk per scene content and
// reference settings so that a sweep (and the next one) renders it once.

#include <atomic>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "image/image.h"
#include "scene/scene.h"
#include "sdf/glsl_sources.h"

namespace sdfwb::tradeoff {

struct ReferenceOptions {
    // epsilon and the ray weight cutoff / tightening; max steps and shadow
    // steps x tightening (up to the format's limits); max_depth at its limit
    double tightening = 10;
    int minimumAa = 1;  // the reference uses at least this AA, and at least the scene's
};

// `scene` at the measured size with the reference's settings.
scene::Scene referenceScene(const scene::Scene& scene, const ReferenceOptions& options);

// Hex key of everything the reference image depends on: the reference scene
// (without its name and description), the shared shading code the renderer
// runs (`shadingCode`, sdf::sharedShadingCode() unless a test gives another)
// and the renderer's version.
std::string referenceKey(const scene::Scene& referenceScene, std::string_view shadingCode = sdf::sharedShadingCode());

// The cached frame, or nothing when the cache has no valid one of that size.
std::optional<image::Frame> loadReference(const std::filesystem::path& cacheDir, const std::string& key, int width,
                                          int height);
// Creates the folder if needed; writes atomically. Throws std::runtime_error naming the path.
void storeReference(const std::filesystem::path& cacheDir, const std::string& key, const image::Frame& frame);

struct ReferenceFrame {
    image::Frame frame;
    bool fromCache = false;
    double seconds = 0;  // rendering time (0 when cached)
};

// Loads or renders (and stores) the reference of `scene`; nothing when cancelled.
std::optional<ReferenceFrame> obtainReference(const scene::Scene& referenceScene, const std::filesystem::path& cacheDir,
                                              const std::atomic<bool>* cancel);

}  // namespace sdfwb::tradeoff
