#pragma once
// Quality presets for the workbench's render panel: draft, interactive and
// final. One table (presets.cpp), its values read off the Pareto fronts of
// docs/speed-vs-error.md; a preset sets the quality knobs and leaves the
// image size, distances and the look (shadow technique, lighting) alone.

#include <span>
#include <string_view>

#include "scene/scene.h"

namespace sdfwb::tradeoff {

struct QualityPreset {
    std::string_view name;
    std::string_view why;         // what the fronts showed, for the tooltip
    int aa;
    double epsilonPixels;         // epsilon in pixel mode: scale-free, so one value suits every scene
    int maxSteps;
    double shadowStepsFactor;     // of the format's default shadow steps
    int aoSamples;                // when the scene uses AO at all
    double stepRelaxation;
};

std::span<const QualityPreset> qualityPresets();

// `render` with the preset applied.
scene::RenderSettings applyPreset(const QualityPreset& preset, scene::RenderSettings render);

}  // namespace sdfwb::tradeoff
