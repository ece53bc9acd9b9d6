#include "tradeoff/pareto.h"

#include <algorithm>
#include <numeric>

namespace sdfwb::tradeoff {

std::vector<size_t> paretoFront(std::span<const CostError> points) {
    std::vector<size_t> order(points.size());
    std::iota(order.begin(), order.end(), size_t{0});
    // by cost, then error, then index: a point is on the front when its error
    // is below every error seen before it
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
        if (points[a].cost != points[b].cost) return points[a].cost < points[b].cost;
        return points[a].error < points[b].error;
    });
    std::vector<size_t> front;
    for (size_t i : order) {
        if (front.empty() || points[i].error < points[front.back()].error) front.push_back(i);
    }
    return front;
}

std::optional<size_t> cheapestWithin(std::span<const CostError> points, double maxError) {
    std::optional<size_t> best;
    for (size_t i = 0; i < points.size(); ++i) {
        if (!(points[i].error <= maxError)) continue;
        if (!best || points[i].cost < points[*best].cost ||
            (points[i].cost == points[*best].cost && points[i].error < points[*best].error)) {
            best = i;
        }
    }
    return best;
}

}  // namespace sdfwb::tradeoff
