#pragma once
// Which settings a sweep renders for one scene: the scene's own, then each
// knob's values one at a time around it (the other settings at the scene's).

#include <optional>
#include <string>
#include <vector>

#include "scene/scene.h"
#include "tradeoff/knobs.h"

namespace sdfwb::tradeoff {

struct KnobRequest {
    const Knob* knob = nullptr;
    std::vector<double> values;  // empty: the knob's defaults for each scene
};

// "name" or "name=v1,v2,..." per item; an empty list selects every knob with its
// defaults. Throws std::invalid_argument with a one-line message.
std::vector<KnobRequest> parseKnobRequests(const std::vector<std::string>& specs);

struct Setting {
    const Knob* knob = nullptr;  // nullptr: the scene's own settings
    double value = 0;
    std::string label;           // "default" or "name=value"
    scene::Scene scene;          // the scene with this setting applied
};

struct SkippedKnob {
    std::string knob;
    std::string reason;
};

struct SweepPlan {
    std::vector<Setting> settings;     // [0] is the default; then grouped by knob, cheapest value first
    std::vector<SkippedKnob> notSwept; // knobs that do nothing for this scene, and why
};

// `base` is the scene at the measured size. A value the scene format rejects is
// an error (std::invalid_argument naming knob and value) when the user gave
// it, and is left out when it is a default.
SweepPlan planSweep(const scene::Scene& base, const std::vector<KnobRequest>& requests);

// How far each knob's chosen value may be from the default's error for tunedSetting.
struct TuningCandidate {
    const Setting* setting;
    double seconds;  // summed over backends
    double error;    // mean display error, the largest over backends
};

// The one-knob settings combined: per knob the fastest value whose error is at
// most `defaultError + slack` and that is faster than the default
// (`defaultSeconds`); nothing when no knob qualifies. Labelled "tuned: a=1 b=2".
std::optional<Setting> tunedSetting(const scene::Scene& base, const std::vector<TuningCandidate>& candidates,
                                    double defaultSeconds, double defaultError, double slack);

// `tuned` with the step relaxation at the default's, labelled "tuned, plain
// steps": what the other knobs save without relaxation. Nothing when `tuned`
// leaves the relaxation as it is or changes nothing else.
std::optional<Setting> withoutRelaxation(const scene::Scene& base, const Setting& tuned);

}  // namespace sdfwb::tradeoff
