// The Pareto front and the cheapest setting within a tolerance.

#include <gtest/gtest.h>

#include "tradeoff/pareto.h"

namespace sdfwb::tradeoff {
namespace {

TEST(ParetoFront, KeepsExactlyThePointsNoOtherBeatsOnBoth) {
    //                               0          1          2          3          4          5
    std::vector<CostError> points = {{3, 1.0}, {1, 5.0}, {2, 2.0}, {2.5, 3.0}, {4, 1.0}, {5, 0.5}};
    // 3 is beaten by 2 (cheaper and closer), 4 by 0 (same error, dearer)
    EXPECT_EQ(paretoFront(points), (std::vector<size_t>{1, 2, 0, 5}));
}

TEST(ParetoFront, SortsByCostAndKeepsTheFirstOfIdenticalPoints) {
    std::vector<CostError> points = {{2, 1.0}, {1, 2.0}, {2, 1.0}, {1, 2.0}};
    EXPECT_EQ(paretoFront(points), (std::vector<size_t>{1, 0}));
}

TEST(ParetoFront, AtEqualCostOnlyTheSmallestErrorStays) {
    std::vector<CostError> points = {{1, 3.0}, {1, 2.0}, {1, 4.0}};
    EXPECT_EQ(paretoFront(points), (std::vector<size_t>{1}));
}

TEST(ParetoFront, OfNothingIsEmptyAndOfOnePointIsIt) {
    EXPECT_TRUE(paretoFront({}).empty());
    std::vector<CostError> one = {{7, 7}};
    EXPECT_EQ(paretoFront(one), (std::vector<size_t>{0}));
}

TEST(ParetoFront, EveryPointOffTheFrontIsDominatedByOneOnIt) {
    std::vector<CostError> points;
    for (int i = 0; i < 40; ++i) points.push_back({double((i * 37) % 23), double((i * 11) % 17)});
    std::vector<size_t> front = paretoFront(points);
    for (size_t i = 0; i < points.size(); ++i) {
        bool onFront = std::find(front.begin(), front.end(), i) != front.end();
        bool dominated = false;
        for (size_t j : front) {
            if (j == i) continue;
            bool noWorse = points[j].cost <= points[i].cost && points[j].error <= points[i].error;
            bool better = points[j].cost < points[i].cost || points[j].error < points[i].error;
            dominated = dominated || (noWorse && (better || j < i));
        }
        EXPECT_NE(onFront, dominated) << "point " << i;
    }
}

TEST(CheapestWithin, PicksTheLeastCostUnderTheToleranceOrNothing) {
    std::vector<CostError> points = {{5, 0.2}, {1, 3.0}, {2, 0.9}, {2, 0.5}, {3, 1.0}};
    EXPECT_EQ(cheapestWithin(points, 1.0), 3u);  // cost 2, the smaller error of the two
    EXPECT_EQ(cheapestWithin(points, 0.3), 0u);
    EXPECT_EQ(cheapestWithin(points, 3.0), 1u);
    EXPECT_FALSE(cheapestWithin(points, 0.1));
}

}  // namespace
}  // namespace sdfwb::tradeoff
