#include "tradeoff/measurements.h"

#include <algorithm>
#include <cstdlib>

#include <nlohmann/json.hpp>

#include "io/atomic_file.h"
#include "scene/scene_json.h"
#include "tradeoff/cache_key.h"

namespace sdfwb::tradeoff {
namespace {

using json = nlohmann::ordered_json;

std::filesystem::path measurementFile(const std::filesystem::path& dir, const std::string& key) {
    return dir / (key + ".measured.json");
}

// The render block read and written by the scene format's own code.
json renderJson(const scene::RenderSettings& render) {
    scene::Scene s;
    s.render = render;
    return scene::sceneToJson(s)["render"];
}

scene::RenderSettings renderFromJson(const json& render) {
    json wrapper = scene::sceneToJson(scene::Scene{});
    wrapper["render"] = render;
    return scene::sceneFromJson(wrapper).render;
}

bool sameQuality(scene::RenderSettings a, scene::RenderSettings b) {
    a.width = b.width;
    a.height = b.height;
    return a == b;
}

}  // namespace

std::filesystem::path defaultCacheDirectory() {
    const char* xdg = std::getenv("XDG_CACHE_HOME");
    const char* home = std::getenv("HOME");
    std::filesystem::path base = xdg != nullptr && *xdg != '\0' ? std::filesystem::path(xdg)
                                 : home != nullptr            ? std::filesystem::path(home) / ".cache"
                                                              : std::filesystem::temp_directory_path();
    return base / "sdf-workbench" / "references";
}

std::string measurementKey(const scene::Scene& scene, std::string_view shadingCode) {
    scene::Scene keyed = scene;
    keyed.name.clear();
    keyed.description.clear();
    // the look stays in the key: errors are against a reference of that look
    scene::RenderSettings look;
    look.shadows = scene.render.shadows;
    look.lighting = scene.render.lighting;
    look.aoSamples = scene.render.aoSamples > 0 ? 1 : 0;
    look.aoDistance = scene.render.aoDistance;
    keyed.render = look;
    return cacheKey(keyed, shadingCode);
}

void storeMeasurements(const std::filesystem::path& cacheDir, const std::string& key, const SceneMeasurements& m) {
    SceneMeasurements merged = m;
    std::optional<SceneMeasurements> stored = loadMeasurements(cacheDir, key);
    if (stored && stored->backends == m.backends) {
        merged = *stored;
        for (const MeasuredPoint& p : m.points) {
            auto same = std::find_if(merged.points.begin(), merged.points.end(),
                                     [&](const MeasuredPoint& o) { return sameQuality(o.render, p.render); });
            if (same != merged.points.end()) {
                *same = p;
            } else {
                merged.points.push_back(p);
            }
        }
    }
    json points = json::array();
    for (const MeasuredPoint& p : merged.points) {
        points.push_back({{"render", renderJson(p.render)}, {"seconds", p.seconds}, {"mean_error", p.meanError}});
    }
    json root = {{"backends", merged.backends}, {"points", points}};
    std::error_code error;
    std::filesystem::create_directories(cacheDir, error);
    if (error) throw std::runtime_error("cannot create " + cacheDir.string() + ": " + error.message());
    io::writeTextAtomically(measurementFile(cacheDir, key), root.dump(1));
}

std::optional<SceneMeasurements> loadMeasurements(const std::filesystem::path& cacheDir, const std::string& key) {
    std::filesystem::path file = measurementFile(cacheDir, key);
    std::error_code error;
    if (!std::filesystem::exists(file, error)) return std::nullopt;
    try {
        json root = json::parse(io::readTextFile(file));
        SceneMeasurements m;
        m.backends = root.at("backends").get<std::vector<std::string>>();
        for (const json& p : root.at("points")) {
            m.points.push_back({renderFromJson(p.at("render")), p.at("seconds").get<std::vector<double>>(),
                                p.at("mean_error").get<double>()});
        }
        return m;
    } catch (const std::exception&) {
        return std::nullopt;  // a stale or damaged cache entry is no measurement
    }
}

std::optional<ErrorEstimate> estimateError(const SceneMeasurements& measured, const scene::RenderSettings& render) {
    if (measured.points.empty()) return std::nullopt;
    const MeasuredPoint& reference = measured.points.front();
    for (const MeasuredPoint& p : measured.points) {
        if (!sameQuality(p.render, render)) continue;
        double speedup = !p.seconds.empty() && p.seconds[0] > 0 && !reference.seconds.empty()
                             ? reference.seconds[0] / p.seconds[0]
                             : 0;
        return ErrorEstimate{p.meanError, speedup};
    }
    return std::nullopt;
}

const SceneMeasurements* MeasurementLookup::forScene(const scene::Scene& scene, std::uint64_t revision) {
    if (revision_ != revision) {
        revision_ = revision;
        std::string key = measurementKey(scene);
        if (key != key_) {
            key_ = key;
            measured_ = loadMeasurements(cacheDir_, key_);
        }
    }
    return measured_ ? &*measured_ : nullptr;
}

}  // namespace sdfwb::tradeoff
