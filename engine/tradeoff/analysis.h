#pragma once
// What a scene's measurements say, per backend: the Pareto front of time
// against mean display error, and the cheapest setting close enough to the
// reference. The report, the plots and the workbench's presets read it.

#include <optional>
#include <vector>

#include "tradeoff/pareto.h"
#include "tradeoff/sweep.h"

namespace sdfwb::tradeoff {

// "Within the reference": mean display error at most this many levels of 255.
inline constexpr double kErrorTolerance = 1.0;

struct BackendAnalysis {
    std::vector<CostError> points;          // per result: (median seconds, mean error in levels)
    std::vector<size_t> front;              // indices into the scene's results, by increasing time
    std::optional<size_t> withinTolerance;  // cheapest result within kErrorTolerance
    bool defaultOnFront = false;            // result 0 is the scene's own setting
};

BackendAnalysis analyse(const SceneResult& scene, size_t backend);

// How much faster than the default, on every backend, a setting must be for
// the report to suggest it as the scene's default: identical images at
// 128x72 have measured up to 1.4 times apart, so less could be noise.
inline constexpr double kDefaultChangeSpeedup = 1.5;

// The setting the measurements suggest as the scene's default (docs/scene-defaults.md):
// of the results at least kDefaultChangeSpeedup times faster than the default
// on every backend and, on every backend, no further from the reference than
// the default or kErrorTolerance, whichever is more, the one of least total
// time (then of least error). Nothing when no result qualifies, or when a
// result lacks a backend's measurement or measured no time.
std::optional<size_t> suggestedDefault(const SceneResult& scene);

}  // namespace sdfwb::tradeoff
