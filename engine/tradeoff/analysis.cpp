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

}  // namespace sdfwb::tradeoff
