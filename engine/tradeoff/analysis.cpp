#include "tradeoff/analysis.h"

#include <algorithm>

namespace sdfwb::tradeoff {

BackendAnalysis analyse(const SceneResult& scene, size_t backend) {
    BackendAnalysis a;
    for (const SettingResult& r : scene.results) {
        const Measurement& m = r.byBackend[backend];
        a.points.push_back({m.seconds, m.error.display.meanAbs});
    }
    a.front = paretoFront(a.points);
    a.withinTolerance = cheapestWithin(a.points, kErrorTolerance);
    a.defaultOnFront = !a.points.empty() && std::find(a.front.begin(), a.front.end(), size_t{0}) != a.front.end();
    return a;
}

std::optional<size_t> suggestedDefault(const SceneResult& scene) {
    if (scene.results.empty() || scene.results[0].byBackend.empty()) return std::nullopt;
    const std::vector<Measurement>& current = scene.results[0].byBackend;
    std::optional<size_t> best;
    double bestSeconds = 0, bestError = 0;
    for (size_t i = 1; i < scene.results.size(); ++i) {
        const std::vector<Measurement>& candidate = scene.results[i].byBackend;
        bool qualifies = candidate.size() == current.size();
        for (size_t b = 0; qualifies && b < candidate.size(); ++b) {
            double allowed = std::max(kErrorTolerance, current[b].error.display.meanAbs);
            qualifies = candidate[b].seconds > 0 &&
                        candidate[b].seconds * kDefaultChangeSpeedup <= current[b].seconds &&
                        candidate[b].error.display.meanAbs <= allowed;
        }
        double seconds = totalSeconds(scene.results[i]), error = worstMeanError(scene.results[i]);
        bool better = !best || seconds < bestSeconds || (seconds == bestSeconds && error < bestError);
        if (qualifies && better) {
            best = i;
            bestSeconds = seconds;
            bestError = error;
        }
    }
    return best;
}

}  // namespace sdfwb::tradeoff
