#pragma once
// The quality knobs the speed-against-error sweep varies. Each one is a row
// of the render settings table (scene/settings_table.h), which gives its name,
// its choices, whether it is whole and how it is read and written; knobs.cpp
// adds only what the sweep needs beyond the row: when the knob does nothing,
// the values swept by default, and what else changes with it.

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "scene/scene.h"
#include "scene/settings_table.h"

namespace sdfwb::tradeoff {

struct Knob {
    const scene::Setting<scene::RenderSettings>* setting;  // its row
    std::string_view name;                  // the row's key: in the scene's JSON render block and on the command line
    std::vector<std::string_view> choices;  // names of an enumerated setting's codes (empty: numeric)
    bool integral = false;                  // numeric values are whole numbers
    // (Ranges are the scene format's: a swept scene is validated by the scene reader.)

    // Called by set() before the new value is written; may adjust other
    // settings so the image stays comparable (epsilon_mode converts epsilon
    // between its units). Null when nothing else changes.
    void (*adjust)(scene::Scene& scene, double value);
    // Why the knob does nothing for `scene` ("" when it does something).
    std::string (*inert)(const scene::Scene& scene);
    // Values swept when the command line names none, without the scene's own.
    std::vector<double> (*defaults)(const scene::Scene& scene);

    // The setting's value in `scene` (an enumerated setting: the index of its choice).
    double get(const scene::Scene& scene) const;
    void set(scene::Scene& scene, double value) const;
};

std::span<const Knob> knobs();
const Knob* findKnob(std::string_view name);

// "0.25", "128" or a choice's name; throws std::invalid_argument naming the knob.
double parseKnobValue(const Knob& knob, std::string_view text);
std::string formatKnobValue(const Knob& knob, double value);

}  // namespace sdfwb::tradeoff
