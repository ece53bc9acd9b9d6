// Which setting the measurements suggest as a scene's default.

#include <gtest/gtest.h>

#include "tradeoff/analysis.h"

namespace sdfwb::tradeoff {
namespace {

struct Point {
    double seconds;
    double error;  // mean levels of 255
};

// A scene whose result i was measured at points[i][backend]; result 0 is the default.
SceneResult measured(const std::vector<std::vector<Point>>& points) {
    SceneResult scene;
    for (size_t i = 0; i < points.size(); ++i) {
        SettingResult r;
        r.setting.label = i == 0 ? "default" : "setting " + std::to_string(i);
        for (Point p : points[i]) {
            Measurement m;
            m.seconds = p.seconds;
            m.error.display.meanAbs = p.error;
            r.byBackend.push_back(m);
        }
        scene.results.push_back(r);
    }
    return scene;
}

TEST(SuggestedDefault, IsTheCheapestSettingFastEnoughAndCloseEnoughOnEveryBackend) {
    SceneResult scene = measured({
        {{0.30, 0.5}, {0.10, 0.5}},  // the default
        {{0.10, 0.9}, {0.03, 0.9}},  // 3x faster, within 1/255: qualifies
        {{0.05, 1.2}, {0.02, 1.2}},  // cheaper, but beyond 1/255 and the default's error
        {{0.12, 0.2}, {0.05, 0.2}},  // qualifies too, but dearer than 1
        {{0.15, 0.5}, {0.09, 0.5}},  // 2x on one backend, 1.1x on the other
    });
    EXPECT_EQ(suggestedDefault(scene), std::optional<size_t>(1));
}

TEST(SuggestedDefault, AllowsTheDefaultsOwnErrorWhenItIsBeyondTheTolerance) {
    SceneResult scene = measured({{{0.30, 3.0}}, {{0.10, 2.9}}, {{0.05, 3.1}}});
    EXPECT_EQ(suggestedDefault(scene), std::optional<size_t>(1));
}

TEST(SuggestedDefault, OfTwoEquallyFastSettingsIsTheCloserOne) {
    SceneResult scene = measured({{{0.30, 0.5}}, {{0.10, 0.9}}, {{0.10, 0.3}}});
    EXPECT_EQ(suggestedDefault(scene), std::optional<size_t>(2));
}

TEST(SuggestedDefault, IgnoresResultsWithoutTimeOrWithoutEveryBackend) {
    EXPECT_EQ(suggestedDefault(measured({{}, {}})), std::nullopt);
    EXPECT_EQ(suggestedDefault(measured({{{0.30, 0.5}, {0.10, 0.5}}, {{0.05, 0.5}}})), std::nullopt);
    EXPECT_EQ(suggestedDefault(measured({{{0.30, 0.5}}, {{0.0, 0.5}}})), std::nullopt);
}

TEST(SuggestedDefault, IsNothingWhenNoSettingIsFasterByTheMargin) {
    SceneResult scene = measured({{{0.30, 0.5}}, {{0.21, 0.4}}, {{0.25, 0.1}}});
    EXPECT_EQ(suggestedDefault(scene), std::nullopt);
    EXPECT_EQ(suggestedDefault(SceneResult{}), std::nullopt);
}

}  // namespace
}  // namespace sdfwb::tradeoff
