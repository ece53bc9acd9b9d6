#pragma once
// What a sweep measured for a scene, kept next to its cached references so the
// workbench can say how far the current settings are from the reference and
// what they cost, without measuring again.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "scene/scene.h"
#include "sdf/glsl_sources.h"

namespace sdfwb::tradeoff {

struct MeasuredPoint {
    scene::RenderSettings render;  // at the measured size
    std::vector<double> seconds;   // median per backend
    double meanError = 0;          // levels of 255, the largest over backends
};

struct SceneMeasurements {
    std::vector<std::string> backends;
    std::vector<MeasuredPoint> points;  // [0] is the scene's default setting when measured
};

// $XDG_CACHE_HOME/sdf-workbench/references (default ~/.cache/...): the tradeoff
// command's references and measurements.
std::filesystem::path defaultCacheDirectory();

// Hex key of a scene's content and look (shadow technique, lighting, whether
// AO is on, AO distance), without its quality settings, name and description:
// edits of quality settings keep finding the measurements, and scenes that
// differ only in quality settings share them. The shared shading code
// (`shadingCode`, sdf::sharedShadingCode() unless a test gives another) and
// the renderer's version are in it too: measurements taken by an older
// renderer, against its references, are not shown for a newer one.
std::string measurementKey(const scene::Scene& scene, std::string_view shadingCode = sdf::sharedShadingCode());

// Adds `m`'s points to those stored under `key` (a point of equal settings,
// size aside, is replaced; the first point stays first). Writes atomically;
// throws std::runtime_error naming the path.
void storeMeasurements(const std::filesystem::path& cacheDir, const std::string& key, const SceneMeasurements& m);
// Nothing when absent or unreadable.
std::optional<SceneMeasurements> loadMeasurements(const std::filesystem::path& cacheDir, const std::string& key);

struct ErrorEstimate {
    double meanError = 0;          // levels of 255
    double speedupOverDefault = 0; // the first stored point's (a sweep's default) time over this one's, first backend
};

// The measured point whose settings equal `render` (size aside); nothing when
// these settings were not measured.
std::optional<ErrorEstimate> estimateError(const SceneMeasurements& measured, const scene::RenderSettings& render);

// The measurements of the scene an editor shows, loaded when its content
// changes (checked by revision, so a frame costs nothing when nothing changed).
class MeasurementLookup {
public:
    explicit MeasurementLookup(std::filesystem::path cacheDir) : cacheDir_(std::move(cacheDir)) {}
    const SceneMeasurements* forScene(const scene::Scene& scene, std::uint64_t revision);

private:
    std::filesystem::path cacheDir_;
    std::optional<std::uint64_t> revision_;
    std::string key_;
    std::optional<SceneMeasurements> measured_;
};

}  // namespace sdfwb::tradeoff
