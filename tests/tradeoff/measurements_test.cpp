// The sweep's measurements as the workbench reads them back, and the presets.

#include <filesystem>

#include <gtest/gtest.h>

#include "scene/scene_json.h"
#include "tradeoff/measurements.h"
#include "tradeoff/presets.h"

namespace sdfwb::tradeoff {
namespace {

namespace fs = std::filesystem;

TEST(MeasurementKey, IgnoresRenderSettingsAndNamesButNotContent) {
    scene::Scene s;
    std::string key = measurementKey(s);
    scene::Scene tuned = s;
    tuned.render.epsilon = 0.5;
    tuned.render.aa = 3;
    tuned.name = "x";
    EXPECT_EQ(measurementKey(tuned), key);
    scene::Scene lit = s;
    lit.lights.push_back(scene::Light{});
    EXPECT_NE(measurementKey(lit), key);
    scene::Scene viewed = s;
    viewed.camera.elevation = 40;
    EXPECT_NE(measurementKey(viewed), key);
    scene::Scene shadowless = s;
    shadowless.render.shadows = scene::ShadowMode::None;  // another look, another reference
    EXPECT_NE(measurementKey(shadowless), key);
    scene::Scene occluded = s;
    occluded.render.aoSamples = 4;
    EXPECT_NE(measurementKey(occluded), key);
    scene::Scene moreSamples = occluded;
    moreSamples.render.aoSamples = 8;
    EXPECT_EQ(measurementKey(moreSamples), measurementKey(occluded));
}

// Measurements are errors against a reference and times of a renderer: a
// renderer whose shading code changed measures again rather than showing the
// old figures in the workbench.
TEST(MeasurementKey, ChangesWithTheShadingCode) {
    scene::Scene s;
    EXPECT_EQ(measurementKey(s), measurementKey(s, sdf::sharedShadingCode()));
    EXPECT_NE(measurementKey(s, "the shading code changed"), measurementKey(s));
}

SceneMeasurements twoPoints() {
    scene::RenderSettings fine, coarse;
    fine.width = coarse.width = 160;
    coarse.epsilon = 0.004;
    coarse.stepRelaxation = 1.4;
    return {{"cpu", "gl"}, {{fine, {2.0, 0.5}, 0.25}, {coarse, {0.8, 0.25}, 1.5}}};
}

TEST(EstimateError, FindsTheMeasuredSettingsWhateverTheImageSize) {
    SceneMeasurements m = twoPoints();
    scene::RenderSettings current = m.points[1].render;
    current.width = 960;
    current.height = 540;
    std::optional<ErrorEstimate> e = estimateError(m, current);
    ASSERT_TRUE(e);
    EXPECT_DOUBLE_EQ(e->meanError, 1.5);
    EXPECT_DOUBLE_EQ(e->speedupOverDefault, 2.5);
    current.maxSteps += 1;
    EXPECT_FALSE(estimateError(m, current));
}

class MeasurementFiles : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("sdfwb_measured_" + std::to_string(::getpid()) + "_" +
                                            ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    fs::path dir_;
};

TEST_F(MeasurementFiles, RoundTripAndDamagedFilesAreNoMeasurement) {
    SceneMeasurements m = twoPoints();
    storeMeasurements(dir_, "k", m);
    std::optional<SceneMeasurements> back = loadMeasurements(dir_, "k");
    ASSERT_TRUE(back);
    EXPECT_EQ(back->backends, m.backends);
    ASSERT_EQ(back->points.size(), 2u);
    EXPECT_EQ(back->points[1].render, m.points[1].render);
    EXPECT_EQ(back->points[1].seconds, m.points[1].seconds);
    EXPECT_FALSE(loadMeasurements(dir_, "other"));
    // a second sweep adds its points and replaces those of equal settings
    SceneMeasurements again = twoPoints();
    again.points[0].meanError = 0.125;
    again.points[1].render.maxSteps = 64;
    storeMeasurements(dir_, "k", again);
    std::optional<SceneMeasurements> merged = loadMeasurements(dir_, "k");
    ASSERT_TRUE(merged);
    ASSERT_EQ(merged->points.size(), 3u);
    EXPECT_DOUBLE_EQ(merged->points[0].meanError, 0.125);
    EXPECT_EQ(merged->points[1].render, m.points[1].render);
    EXPECT_EQ(merged->points[2].render.maxSteps, 64);
    fs::resize_file(dir_ / "k.measured.json", 20);
    EXPECT_FALSE(loadMeasurements(dir_, "k"));
}

TEST_F(MeasurementFiles, TheLookupLoadsOncePerContentAndFollowsEdits) {
    scene::Scene s;
    storeMeasurements(dir_, measurementKey(s), twoPoints());
    MeasurementLookup lookup(dir_);
    const SceneMeasurements* first = lookup.forScene(s, 1);
    ASSERT_NE(first, nullptr);
    fs::remove_all(dir_);
    EXPECT_EQ(lookup.forScene(s, 1), first);  // same revision: not read again
    scene::Scene quality = s;
    quality.render.aa = 4;
    EXPECT_EQ(lookup.forScene(quality, 2), first);  // same content key: kept
    scene::Scene edited = s;
    edited.root.children.push_back(scene::Node::make(scene::NodeKind::Sphere));
    EXPECT_EQ(lookup.forScene(edited, 3), nullptr);
}

TEST(QualityPresets, RunFromCheapToFineAndAreValidScenes) {
    std::span<const QualityPreset> presets = qualityPresets();
    ASSERT_EQ(presets.size(), 3u);
    EXPECT_EQ(presets[0].name, "draft");
    EXPECT_EQ(presets[2].name, "final");
    for (size_t i = 1; i < presets.size(); ++i) {
        EXPECT_LE(presets[i - 1].aa, presets[i].aa);
        EXPECT_GE(presets[i - 1].epsilonPixels, presets[i].epsilonPixels);
        EXPECT_LE(presets[i - 1].shadowStepsFactor, presets[i].shadowStepsFactor);
    }
    scene::Scene s;
    s.render.aoSamples = 0;
    for (const QualityPreset& p : presets) {
        scene::Scene applied = s;
        applied.render = applyPreset(p, s.render);
        EXPECT_NO_THROW(scene::sceneFromJson(scene::sceneToJson(applied))) << p.name;
        EXPECT_EQ(applied.render.aoSamples, 0) << "a preset turned AO on";
        EXPECT_EQ(applied.render.epsilonMode, scene::EpsilonMode::Pixel);
        EXPECT_EQ(applied.render.width, s.render.width);
        EXPECT_EQ(applied.render.shadows, s.render.shadows);
    }
}

}  // namespace
}  // namespace sdfwb::tradeoff
