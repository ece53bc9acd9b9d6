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
    std::vector<CostError> points;       // per result: (median seconds, mean error in levels)
    std::vector<size_t> front;           // indices into the scene's results, by increasing time
    std::optional<size_t> withinTolerance;  // cheapest result within kErrorTolerance
    bool defaultOnFront = false;         // result 0 is the scene's own setting
};

BackendAnalysis analyse(const SceneResult& scene, size_t backend);

}  // namespace sdfwb::tradeoff
