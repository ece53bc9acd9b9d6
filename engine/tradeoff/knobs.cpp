#include "tradeoff/knobs.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <type_traits>
#include <variant>

#include "program/bounds.h"
#include "scene/camera_frame.h"

namespace sdfwb::tradeoff {
namespace {

using scene::Scene;
using Row = scene::Setting<scene::RenderSettings>;

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

std::string noMirrorsOrGlass(const Scene& s) { return s.hasMirrorsOrGlass() ? "" : "no mirrors or glass"; }

std::string noShadowRays(const Scene& s) {
    if (s.lights.empty()) return "no lights";
    return s.render.shadows == scene::ShadowMode::None ? "shadows off" : "";
}

// The same threshold at the camera's target distance in the other unit.
void convertEpsilon(Scene& s, double value) {
    auto mode = static_cast<scene::EpsilonMode>(static_cast<int>(value));
    if (mode == s.render.epsilonMode) return;
    double footprint = subsampleFootprint(s);
    s.render.epsilon = mode == scene::EpsilonMode::Pixel ? s.render.epsilon / footprint : s.render.epsilon * footprint;
}

// The knob over the render setting `key`: name, choices, wholeness and access come from its row.
Knob knob(std::string_view key, std::string (*inert)(const Scene&), std::vector<double> (*defaults)(const Scene&),
          void (*adjust)(Scene&, double) = nullptr) {
    for (const Row& row : scene::renderSettings()) {
        if (row.key != key) continue;
        if (row.type != scene::SettingType::Integer && row.type != scene::SettingType::Real &&
            row.type != scene::SettingType::Choice) {
            throw std::logic_error("knob " + std::string(key) + ": not a numeric or enumerated render setting");
        }
        std::vector<std::string_view> choices(row.choices.begin(), row.choices.end());
        return {&row, row.key, choices, row.type != scene::SettingType::Real, adjust, inert, defaults};
    }
    throw std::logic_error("knob " + std::string(key) + ": no such render setting");
}

std::vector<Knob> makeKnobs() {
    std::vector<Knob> k;
    // Each list starts with its cheapest value: a knob whose cheapest value
    // leaves the image unchanged is not swept further (sweep.cpp).
    k.push_back(knob("epsilon", always, [](const Scene& s) {
        return scaled(s.render.epsilon, {4, 2, 0.5, 0.25}, false);
    }));
    k.push_back(knob(
        "epsilon_mode", always,
        [](const Scene& s) {
            return except({0, 1}, static_cast<double>(s.render.epsilonMode));
        },
        convertEpsilon));
    k.push_back(knob("max_steps", always, [](const Scene& s) {
        return scaled(s.render.maxSteps, {0.25, 0.5, 2}, true);
    }));
    k.push_back(knob("max_distance", always, [](const Scene& s) {
        return scaled(s.render.maxDistance, {0.25, 0.5, 2}, false);
    }));
    k.push_back(knob(
        "shadows", [](const Scene& s) { return s.lights.empty() ? std::string("no lights") : std::string(); },
        [](const Scene& s) {
            return except({0, 1, 2, 3}, static_cast<double>(s.render.shadows));
        }));
    k.push_back(knob("shadow_steps", noShadowRays, [](const Scene& s) {
        return scaled(s.render.shadowSteps, {0.25, 0.5, 2}, true);
    }));
    // Turning AO on where the scene has it off changes the look, not the
    // quality: only scenes with AO sweep its sample count.
    k.push_back(knob(
        "ao_samples", [](const Scene& s) { return s.render.aoSamples == 0 ? std::string("AO off") : std::string(); },
        [](const Scene& s) {
            return except({0, 1, 2, 4, 8}, static_cast<double>(s.render.aoSamples));
        }));
    k.push_back(knob("aa", always, [](const Scene& s) { return except({1, 2, 3}, static_cast<double>(s.render.aa)); }));
    k.push_back(knob("step_relaxation", always, [](const Scene& s) {
        return except({1.8, 1.6, 1.4, 1.2, 1.0}, s.render.stepRelaxation);
    }));
    // The tracer's knowledge beyond the field (the ground plane along the ray,
    // the scene's bounds for the march and shadow rays; the default) or plain
    // sphere tracing, the speed report's baseline (report.cpp). It changes
    // nothing in a scene with neither a ground nor bounds.
    k.push_back(knob(
        "tracing",
        [](const Scene& s) {
            return s.environment.ground.enabled || program::nodeBounds(s.root).finite()
                       ? std::string()
                       : std::string("no ground, no bounds");
        },
        [](const Scene& s) {
            return except({0, 1}, static_cast<double>(s.render.tracing));
        }));
    // The ray tree's two limits (sdf/glsl/ray_tree.glsl): bounces, and the
    // weight below which a secondary ray is dropped.
    k.push_back(knob("max_depth", noMirrorsOrGlass, [](const Scene& s) {
        return except({0, 1, 2, 3, 4, 6}, static_cast<double>(s.render.maxDepth));
    }));
    k.push_back(knob(
        "ray_weight_cutoff",
        [](const Scene& s) { return s.render.maxDepth == 0 ? std::string("max_depth 0") : noMirrorsOrGlass(s); },
        [](const Scene& s) {
            return except({0.1, 0.03, 0.01, 0.00390625, 0.001}, s.render.rayWeightCutoff);
        }));
    return k;
}

}  // namespace

double Knob::get(const Scene& scene) const {
    return std::visit(
        [&](const auto& member) -> double {
            using M = std::decay_t<decltype(member)>;
            if constexpr (std::is_same_v<M, int scene::RenderSettings::*>) return scene.render.*member;
            if constexpr (std::is_same_v<M, double scene::RenderSettings::*>) return scene.render.*member;
            if constexpr (std::is_same_v<M, scene::ChoiceMember<scene::RenderSettings>>)
                return member.get(scene.render);
            throw std::logic_error("knob " + std::string(name) + ": not numeric");
        },
        setting->member);
}

void Knob::set(Scene& scene, double value) const {
    if (adjust) adjust(scene, value);
    std::visit(
        [&](const auto& member) {
            using M = std::decay_t<decltype(member)>;
            if constexpr (std::is_same_v<M, int scene::RenderSettings::*>) {
                scene.render.*member = static_cast<int>(value);
            } else if constexpr (std::is_same_v<M, double scene::RenderSettings::*>) {
                scene.render.*member = value;
            } else if constexpr (std::is_same_v<M, scene::ChoiceMember<scene::RenderSettings>>) {
                member.set(scene.render, static_cast<int>(value));
            } else {
                throw std::logic_error("knob " + std::string(name) + ": not numeric");
            }
        },
        setting->member);
}

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
