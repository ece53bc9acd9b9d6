#pragma once
// The Pareto front of measured settings: those no other setting beats on both
// cost (time) and error.

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

namespace sdfwb::tradeoff {

struct CostError {
    double cost = 0;   // e.g. seconds
    double error = 0;  // e.g. mean levels of 255
};

// Indices of the points on the front, by increasing cost. A point is dominated
// when another is no worse on both and better on one; of identical points the
// first stays.
std::vector<size_t> paretoFront(std::span<const CostError> points);

// The point of least cost whose error is at most `maxError` (ties: the smaller
// error, then the first).
std::optional<size_t> cheapestWithin(std::span<const CostError> points, double maxError);

}  // namespace sdfwb::tradeoff
