// The ground's box-filtered patterns (material.glsl) in the double build:
// against brute-force averages of the point pattern over the footprint, the
// point sample below the smallest footprint, the mean above the largest, and
// a row of pixels towards the horizon whose colours no longer alias.

#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "sdf/shared.h"

namespace sdfwb::sdf::f64 {
namespace {

// The point pattern's share of secondColor averaged over n x n points of the box.
double bruteForceCoverage(int pattern, double u, double v, double wu, double wv, double halfLine, int n) {
    double sum = 0;
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
            double x = u + wu * ((i + 0.5) / n - 0.5);
            double y = v + wv * ((j + 0.5) / n - 0.5);
            bool second = pattern == GROUND_CHECKER ? checkerWave(x) * checkerWave(y) < 0
                                                    : gridLine(x, halfLine) + gridLine(y, halfLine) > 0;
            sum += second ? 1 : 0;
        }
    }
    return sum / (n * n);
}

TEST(GroundPattern, FilterIsTheAverageOverTheFootprint) {
    const double cell = 0.5, lineWidth = 0.04, halfLine = 0.5 * lineWidth / cell;
    const double points[][4] = {{0.13, 0.71, 0.3, 0.05}, {3.97, -2.2, 1.7, 0.6}, {-0.49, 10.02, 0.02, 4.3},
                                {0.0, 0.0, 0.5, 0.5},    {7.5, 7.5, 2.0, 2.0},   {-12.3, 5.6, 0.011, 0.013}};
    for (int pattern : {GROUND_CHECKER, GROUND_GRID}) {
        for (const auto& q : points) {
            double u = q[0], v = q[1], wu = q[2], wv = q[3];
            double filtered = groundPatternCoverage(vec3(u * cell, 0, v * cell), pattern, cell, lineWidth,
                                                    vec2(wu * cell, wv * cell));
            // 2000^2 points resolve the box's edges to 1/2000 of its width
            EXPECT_NEAR(filtered, bruteForceCoverage(pattern, u, v, wu, wv, halfLine, 2000), 2e-3)
                << pattern << " at " << u << ", " << v << " width " << wu << " x " << wv;
        }
    }
}

TEST(GroundPattern, TinyFootprintIsThePointSample) {
    const double halfLine = 0.05;
    for (double u = -3.0; u < 3.0; u += 0.0173) {
        EXPECT_EQ(filteredCheckerWave(u, 0.0), checkerWave(u));
        EXPECT_EQ(filteredCheckerWave(u, PATTERN_MIN_FOOTPRINT), checkerWave(u));
        EXPECT_EQ(filteredGridLine(u, halfLine, 0.0), gridLine(u, halfLine));
    }
}

TEST(GroundPattern, HugeFootprintIsTheMean) {
    const double halfLine = 0.02;
    const double lineMean = 1 - (1 - 2 * halfLine) * (1 - 2 * halfLine);
    for (double u : {0.0, 0.3, 17.9, -123.4}) {
        for (double w : {1e3, 1e6, 1e30}) {
            vec2 footprint(w, w);
            EXPECT_NEAR(groundPatternCoverage(vec3(u, 0, 2 * u), GROUND_CHECKER, 1.0, 0.04, footprint), 0.5, 1e-3);
            EXPECT_NEAR(groundPatternCoverage(vec3(u, 0, 2 * u), GROUND_GRID, 1.0, 0.04, footprint), lineMean, 1e-3);
        }
    }
}

// Along one image row near the horizon (a camera 1.2 above the floor looking
// 2 degrees below it, 960 pixels across 45 degrees of 540 rows), the filtered
// pattern is close to the pixel's average of 16 x 16 point samples, which the
// single point sample (aliasing) is not. Towards the image's sides the
// footprint is a long thin ellipse at an angle and the filter's box, its
// bounding box, is wider: there the filtered checker is too smooth or keeps
// some of the box filter's ringing, but it does not alias.
TEST(GroundPattern, RowTowardsTheHorizonMatchesSupersampling) {
    const double footprintPerDistance = 2 * std::tan(22.5 * M_PI / 180) / 540;
    const double eyeHeight = 1.2;
    Material base = noMaterial();
    base.diffuse = vec3(1);
    const vec4 q1(0.3, 0, 0.7, 1.0);
    const vec4 q2(0, 0, 0, 0.04);
    for (int pattern : {GROUND_GRID, GROUND_CHECKER}) {
        const vec4 q0(-eyeHeight, pattern, footprintPerDistance, 0);
        const vec4 pointQ0(-eyeHeight, pattern, 0, 0);
        auto diffuseAt = [&](double sx, double sy, vec4 q) {
            vec3 direction(sx * footprintPerDistance, -std::tan(2 * M_PI / 180) + sy * footprintPerDistance, -1.0);
            vec3 p = direction * (eyeHeight / -direction.y);
            return instGround(p, p, q, q1, q2, base).material.diffuse.x;
        };
        double filteredError = 0, pointError = 0, worstFiltered = 0, centralError = 0, centralPointError = 0;
        const int n = 16;
        for (int x = -480; x < 480; ++x) {
            double reference = 0;
            for (int i = 0; i < n; ++i) {
                for (int j = 0; j < n; ++j) reference += diffuseAt(x + (i + 0.5) / n, (j + 0.5) / n - 0.5, pointQ0);
            }
            reference /= n * n;
            double filtered = std::abs(diffuseAt(x + 0.5, 0, q0) - reference);
            double point = std::abs(diffuseAt(x + 0.5, 0, pointQ0) - reference);
            filteredError += filtered;
            pointError += point;
            if (std::abs(x) < 32) {
                worstFiltered = std::max(worstFiltered, filtered);
                centralError += filtered;
                centralPointError += point;
            }
        }
        EXPECT_GT(pointError / 960, 0.05) << pattern;
        EXPECT_LT(filteredError, 0.5 * pointError) << pattern;
        EXPECT_LT(centralError, 0.2 * centralPointError) << pattern;
        EXPECT_LT(worstFiltered, 0.2) << pattern;
        std::printf(
            "pattern %d: mean error against 16x16 supersampling, point %.4f filtered %.4f; central 64 pixels: "
            "point %.4f filtered %.4f (worst %.4f)\n",
            pattern, pointError / 960, filteredError / 960, centralPointError / 64, centralError / 64, worstFiltered);
    }
}

}  // namespace
}  // namespace sdfwb::sdf::f64
