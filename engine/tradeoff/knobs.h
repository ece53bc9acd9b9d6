#pragma once
// The quality knobs the speed-against-error sweep varies: which render setting
// each one is, how its values are read and written, and the values swept by
// default. The list itself lives in knobs.cpp only, so that driving it from the
// engine's settings table is a change of that one file.

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "scene/scene.h"

namespace sdfwb::tradeoff {

struct Knob {
    std::string_view name;                  // as in the scene's JSON render block and on the command line
    std::vector<std::string_view> choices;  // names of an enumerated setting's codes (empty: numeric)
    bool integral = false;                  // numeric values are whole numbers
    // (Ranges are the scene format's: a swept scene is validated by the scene reader.)

    // The setting's value in `scene` (an enumerated setting: the index of its choice).
    double (*get)(const scene::Scene& scene);
    // Sets the value; may adjust other settings so the image stays comparable
    // (epsilon_mode converts epsilon between its units).
    void (*set)(scene::Scene& scene, double value);
    // Why the knob does nothing for `scene` ("" when it does something).
    std::string (*inert)(const scene::Scene& scene);
    // Values swept when the command line names none, without the scene's own.
    std::vector<double> (*defaults)(const scene::Scene& scene);
};

std::span<const Knob> knobs();
const Knob* findKnob(std::string_view name);

// "0.25", "128" or a choice's name; throws std::invalid_argument naming the knob.
double parseKnobValue(const Knob& knob, std::string_view text);
std::string formatKnobValue(const Knob& knob, double value);

}  // namespace sdfwb::tradeoff
