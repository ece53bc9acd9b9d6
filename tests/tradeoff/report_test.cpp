// The report's faster-tracing section measures against plain sphere tracing:
// a scene's default with tracing=plain.

#include <string>

#include <gtest/gtest.h>

#include "tradeoff/knobs.h"
#include "tradeoff/report.h"

namespace sdfwb::tradeoff {
namespace {

SettingResult measured(const char* knobName, double value, std::string label, const scene::Scene& scene,
                       double seconds, double steps, double evaluations, double error) {
    SettingResult r;
    r.setting = {knobName ? findKnob(knobName) : nullptr, value, std::move(label), scene};
    Measurement m;
    m.seconds = seconds;
    m.repetitionSeconds = {seconds};
    m.meanSteps = steps;
    m.meanEvaluations = evaluations;
    m.error.display.meanAbs = error;
    r.byBackend = {m};
    return r;
}

std::string speedupSection(const std::string& report) {
    size_t at = report.find("## Faster tracing against plain sphere tracing");
    return at == std::string::npos ? std::string() : report.substr(at, report.find("\n## ", at + 1) - at);
}

TEST(Report, FasterTracingIsMeasuredAgainstPlainSphereTracing) {
    scene::Scene s;
    s.environment.ground.enabled = true;
    SceneResult scene;
    scene.name = "floor.json";
    scene.scene = s;
    scene.reference = s;
    scene::Scene sphere = s, relaxed = s;
    sphere.render.tracing = scene::Tracing::Plain;
    relaxed.render.stepRelaxation = 1.4;
    scene.results = {measured(nullptr, 0, "default", s, 0.010, 6.0, 12.0, 0.5),
                     measured("tracing", 1, "tracing=plain", sphere, 0.030, 24.0, 30.0, 0.9),
                     measured("step_relaxation", 1.4, "step_relaxation=1.4", relaxed, 0.009, 5.0, 11.0, 0.6)};
    SweepResult result;
    result.backends = {"cpu"};
    result.scenes = {scene};
    std::string section = speedupSection(writeReport(result, {}));
    ASSERT_FALSE(section.empty());
    // plain: tracing=plain's figures; the default 4x fewer steps,
    // 2.5x fewer evaluations, 3x faster; with relaxation too 4.8x, 2.73x, 3.33x
    EXPECT_NE(section.find("| floor.json | cpu | 24.0 | 30.0 |"), std::string::npos) << section;
    EXPECT_NE(section.find("default (bounded tracing) (1 scenes): 4.00x fewer steps, 2.50x fewer evaluations, "
                           "3.00x faster"),
              std::string::npos)
        << section;
    EXPECT_NE(section.find("default, relaxed (1 scenes): 4.80x fewer steps, 2.73x fewer evaluations, 3.33x faster"),
              std::string::npos)
        << section;
    EXPECT_NE(section.find("tuned and relaxed: no scene"), std::string::npos) << section;

    // where the knob changes nothing (no ground, no shadow rays) the default
    // is plain sphere tracing
    scene.scene.environment.ground.enabled = false;
    scene.scene.render.shadows = scene::ShadowMode::None;
    scene.results.erase(scene.results.begin() + 1);
    result.scenes = {scene};
    section = speedupSection(writeReport(result, {}));
    EXPECT_NE(section.find("| floor.json | cpu | 6.0 | 12.0 |"), std::string::npos) << section;
    EXPECT_NE(section.find("default (bounded tracing): no scene"), std::string::npos) << section;
    EXPECT_EQ(section.find("0.00x"), std::string::npos) << "no ratio of nothing: " << section;
}

}  // namespace
}  // namespace sdfwb::tradeoff
