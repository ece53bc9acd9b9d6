#include "tradeoff/presets.h"

#include <algorithm>
#include <cmath>

namespace sdfwb::tradeoff {

std::span<const QualityPreset> qualityPresets() {
    static constexpr QualityPreset kPresets[] = {
        {"draft", "AA 1 and a coarse epsilon: the fronts' cheapest points, several times the error of final",
         1, 2.0, 128, 0.5, 2, 1.2},
        {"interactive", "the scenes' usual settings with relaxed steps: on or near the fronts at their knee",
         1, 0.5, 256, 1.0, 4, 1.2},
        {"final", "AA 2 and a fine epsilon: the fronts' points closest to the reference",
         2, 0.125, 512, 2.0, 8, 1.0},
    };
    return kPresets;
}

scene::RenderSettings applyPreset(const QualityPreset& preset, scene::RenderSettings render) {
    const scene::RenderSettings defaults{};
    render.aa = preset.aa;
    render.epsilonMode = scene::EpsilonMode::Pixel;
    render.epsilon = preset.epsilonPixels;
    render.maxSteps = preset.maxSteps;
    render.shadowSteps = std::max(1, static_cast<int>(std::lround(defaults.shadowSteps * preset.shadowStepsFactor)));
    if (render.aoSamples > 0) render.aoSamples = preset.aoSamples;
    render.stepRelaxation = preset.stepRelaxation;
    return render;
}

}  // namespace sdfwb::tradeoff
