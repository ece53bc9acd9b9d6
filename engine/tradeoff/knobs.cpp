#include "tradeoff/knobs.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "scene/camera_frame.h"
#include "scene/scene_json.h"

namespace sdfwb::tradeoff {
namespace {

using scene::Scene;

// The JSON name of each code of an enumerated render setting, read back from
// the scene writer so the names stay defined once (scene_json.cpp).
template <typename Enum>
std::vector<std::string_view> choiceNames(Enum scene::RenderSettings::*member, std::string_view key, int count) {
    static std::vector<std::string> storage;  // views below point into it
    std::vector<std::string_view> names;
    for (int code = 0; code < count; ++code) {
        Scene probe;
        probe.render.*member = static_cast<Enum>(code);
        storage.push_back(scene::sceneToJson(probe)["render"][std::string(key)].template get<std::string>());
    }
    for (size_t i = storage.size() - static_cast<size_t>(count); i < storage.size(); ++i) names.push_back(storage[i]);
    return names;
}

// Scene units of one sub-sample at the camera's target distance: what a pixel
// epsilon of 1 means there (docs/scene-format.md, epsilon modes).
double subsampleFootprint(const Scene& s) {
    double tanHalfFov = scene::cameraFrame(s.camera).tanHalfFov;
    return s.camera.distance * 2.0 * tanHalfFov / (static_cast<double>(s.render.height) * s.render.aa);
}

std::vector<double> scaled(double value, std::initializer_list<double> factors, bool integral) {
    std::vector<double> values;
    for (double f : factors) {
        double v = integral ? std::max(1.0, std::round(value * f)) : value * f;
        if (v != value && std::find(values.begin(), values.end(), v) == values.end()) values.push_back(v);
    }
    return values;
}

std::vector<double> except(std::vector<double> values, double own) {
    values.erase(std::remove(values.begin(), values.end(), own), values.end());
    return values;
}

std::string always(const Scene&) { return ""; }

std::vector<Knob> makeKnobs() {
    std::vector<Knob> k;
    // Each list starts with its cheapest value: a knob whose cheapest value
    // leaves the image unchanged is not swept further (sweep.cpp).
    k.push_back({"epsilon", {}, false,
                 [](const Scene& s) { return s.render.epsilon; },
                 [](Scene& s, double v) { s.render.epsilon = v; }, always,
                 [](const Scene& s) { return scaled(s.render.epsilon, {4, 2, 0.5, 0.25}, false); }});
    k.push_back({"epsilon_mode", choiceNames(&scene::RenderSettings::epsilonMode, "epsilon_mode", 2), true,
                 [](const Scene& s) { return static_cast<double>(s.render.epsilonMode); },
                 [](Scene& s, double v) {
                     auto mode = static_cast<scene::EpsilonMode>(static_cast<int>(v));
                     if (mode == s.render.epsilonMode) return;
                     // the same threshold at the camera's target distance
                     double footprint = subsampleFootprint(s);
                     s.render.epsilon = mode == scene::EpsilonMode::Pixel ? s.render.epsilon / footprint
                                                                          : s.render.epsilon * footprint;
                     s.render.epsilonMode = mode;
                 },
                 always,
                 [](const Scene& s) { return except({0, 1}, static_cast<double>(s.render.epsilonMode)); }});
    k.push_back({"max_steps", {}, true,
                 [](const Scene& s) { return static_cast<double>(s.render.maxSteps); },
                 [](Scene& s, double v) { s.render.maxSteps = static_cast<int>(v); }, always,
                 [](const Scene& s) { return scaled(s.render.maxSteps, {0.25, 0.5, 2}, true); }});
    k.push_back({"max_distance", {}, false,
                 [](const Scene& s) { return s.render.maxDistance; },
                 [](Scene& s, double v) { s.render.maxDistance = v; }, always,
                 [](const Scene& s) { return scaled(s.render.maxDistance, {0.25, 0.5, 2}, false); }});
    k.push_back({"shadows", choiceNames(&scene::RenderSettings::shadows, "shadows", 4), true,
                 [](const Scene& s) { return static_cast<double>(s.render.shadows); },
                 [](Scene& s, double v) { s.render.shadows = static_cast<scene::ShadowMode>(static_cast<int>(v)); },
                 [](const Scene& s) { return s.lights.empty() ? std::string("no lights") : std::string(); },
                 [](const Scene& s) { return except({0, 1, 2, 3}, static_cast<double>(s.render.shadows)); }});
    k.push_back({"shadow_steps", {}, true,
                 [](const Scene& s) { return static_cast<double>(s.render.shadowSteps); },
                 [](Scene& s, double v) { s.render.shadowSteps = static_cast<int>(v); },
                 [](const Scene& s) {
                     if (s.lights.empty()) return std::string("no lights");
                     return s.render.shadows == scene::ShadowMode::None ? std::string("shadows off") : std::string();
                 },
                 [](const Scene& s) { return scaled(s.render.shadowSteps, {0.25, 0.5, 2}, true); }});
    // Turning AO on where the scene has it off changes the look, not the
    // quality: only scenes with AO sweep its sample count.
    k.push_back({"ao_samples", {}, true,
                 [](const Scene& s) { return static_cast<double>(s.render.aoSamples); },
                 [](Scene& s, double v) { s.render.aoSamples = static_cast<int>(v); },
                 [](const Scene& s) { return s.render.aoSamples == 0 ? std::string("AO off") : std::string(); },
                 [](const Scene& s) { return except({0, 1, 2, 4, 8}, static_cast<double>(s.render.aoSamples)); }});
    k.push_back({"aa", {}, true,
                 [](const Scene& s) { return static_cast<double>(s.render.aa); },
                 [](Scene& s, double v) { s.render.aa = static_cast<int>(v); }, always,
                 [](const Scene& s) { return except({1, 2, 3}, static_cast<double>(s.render.aa)); }});
    k.push_back({"step_relaxation", {}, false,
                 [](const Scene& s) { return s.render.stepRelaxation; },
                 [](Scene& s, double v) { s.render.stepRelaxation = v; }, always,
                 [](const Scene& s) { return except({1.8, 1.6, 1.4, 1.2, 1.0}, s.render.stepRelaxation); }});
    return k;
}

}  // namespace

std::span<const Knob> knobs() {
    static const std::vector<Knob> table = makeKnobs();
    return table;
}

const Knob* findKnob(std::string_view name) {
    for (const Knob& knob : knobs()) {
        if (knob.name == name) return &knob;
    }
    return nullptr;
}

double parseKnobValue(const Knob& knob, std::string_view text) {
    if (!knob.choices.empty()) {
        for (size_t i = 0; i < knob.choices.size(); ++i) {
            if (knob.choices[i] == text) return static_cast<double>(i);
        }
        std::string list;
        for (std::string_view c : knob.choices) list += (list.empty() ? "" : ", ") + std::string(c);
        throw std::invalid_argument(std::string(knob.name) + ": '" + std::string(text) + "' is not one of " + list);
    }
    double value = 0;
    auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) {
        throw std::invalid_argument(std::string(knob.name) + ": '" + std::string(text) + "' is not a number");
    }
    if (knob.integral && value != std::floor(value)) {
        throw std::invalid_argument(std::string(knob.name) + ": '" + std::string(text) + "' is not a whole number");
    }
    return value;
}

std::string formatKnobValue(const Knob& knob, double value) {
    if (!knob.choices.empty()) {
        auto index = static_cast<size_t>(value);
        return index < knob.choices.size() ? std::string(knob.choices[index]) : std::to_string(index);
    }
    std::ostringstream out;
    out.precision(knob.integral ? 12 : 4);
    out << value;
    return out.str();
}

}  // namespace sdfwb::tradeoff
