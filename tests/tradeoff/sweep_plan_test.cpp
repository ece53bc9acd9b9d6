// Which settings a sweep renders: knob parsing, default values around the
// scene's, knobs that do nothing for a scene, values the format rejects.

#include <gtest/gtest.h>

#include "scene/scene_json.h"
#include "tradeoff/sweep_plan.h"

namespace sdfwb::tradeoff {
namespace {

std::vector<std::string> labels(const SweepPlan& plan) {
    std::vector<std::string> out;
    for (const Setting& s : plan.settings) out.push_back(s.label);
    return out;
}

scene::Scene sceneWith(int aoSamples, scene::ShadowMode shadows) {
    scene::Scene s;
    s.render.width = 64;
    s.render.height = 36;
    s.render.aoSamples = aoSamples;
    s.render.shadows = shadows;
    return s;
}

TEST(KnobRequests, NamesAloneOrWithValuesAndEveryKnobWhenNoneIsNamed) {
    std::vector<KnobRequest> all = parseKnobRequests({});
    EXPECT_EQ(all.size(), knobs().size());
    std::vector<KnobRequest> some = parseKnobRequests({"max_steps=64,128", "shadows=hard,none", "aa"});
    ASSERT_EQ(some.size(), 3u);
    EXPECT_EQ(some[0].knob->name, "max_steps");
    EXPECT_EQ(some[0].values, (std::vector<double>{64, 128}));
    EXPECT_EQ(some[1].values, (std::vector<double>{1, 0}));  // codes of "hard", "none"
    EXPECT_TRUE(some[2].values.empty());
}

TEST(KnobRequests, BadSpecsSayWhatIsWrong) {
    auto message = [](std::vector<std::string> specs) {
        try {
            parseKnobRequests(specs);
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_NE(message({"speed"}).find("unknown knob 'speed'"), std::string::npos);
    EXPECT_NE(message({"epsilon=abc"}).find("epsilon: 'abc' is not a number"), std::string::npos);
    EXPECT_NE(message({"max_steps=12.5"}).find("not a whole number"), std::string::npos);
    EXPECT_NE(message({"shadows=blurry"}).find("'blurry' is not one of none, hard, soft, improved"),
              std::string::npos);
    EXPECT_NE(message({"aa", "aa=2"}).find("given twice"), std::string::npos);
}

TEST(SweepPlan, StartsWithTheDefaultAndVariesOneKnobAtATime) {
    scene::Scene base = sceneWith(4, scene::ShadowMode::Soft);
    SweepPlan plan = planSweep(base, parseKnobRequests({"max_steps=64,256,512", "ao_samples=2"}));
    // 256 is the scene's own: it is the default, not swept again
    EXPECT_EQ(labels(plan), (std::vector<std::string>{"default", "max_steps=64", "max_steps=512", "ao_samples=2"}));
    EXPECT_EQ(plan.settings[0].scene, base);
    EXPECT_EQ(plan.settings[2].scene.render.maxSteps, 512);
    EXPECT_EQ(plan.settings[2].scene.render.aoSamples, 4);
    EXPECT_EQ(plan.settings[3].scene.render.aoSamples, 2);
    EXPECT_EQ(plan.settings[3].scene.render.maxSteps, 256);
}

TEST(SweepPlan, DefaultValuesSurroundTheScenesAndStartWithTheCheapest) {
    scene::Scene base = sceneWith(4, scene::ShadowMode::Soft);
    base.render.epsilon = 0.002;
    SweepPlan plan = planSweep(base, parseKnobRequests({"epsilon", "shadow_steps", "aa"}));
    EXPECT_EQ(labels(plan), (std::vector<std::string>{"default", "epsilon=0.008", "epsilon=0.004", "epsilon=0.001",
                                                      "epsilon=0.0005", "shadow_steps=16", "shadow_steps=32",
                                                      "shadow_steps=128", "aa=2", "aa=3"}));
}

TEST(SweepPlan, KnobsThatDoNothingForTheSceneAreNotSwept) {
    SweepPlan plan = planSweep(sceneWith(0, scene::ShadowMode::None), parseKnobRequests({}));
    ASSERT_EQ(plan.notSwept.size(), 5u);
    EXPECT_EQ(plan.notSwept[0].knob, "shadow_steps");
    EXPECT_EQ(plan.notSwept[0].reason, "shadows off");
    EXPECT_EQ(plan.notSwept[1].knob, "ao_samples");
    EXPECT_EQ(plan.notSwept[1].reason, "AO off");
    EXPECT_EQ(plan.notSwept[2].knob, "tracing");
    EXPECT_EQ(plan.notSwept[2].reason, "no ground, no bounds");
    EXPECT_EQ(plan.notSwept[3].knob, "max_depth");
    EXPECT_EQ(plan.notSwept[3].reason, "no mirrors or glass");
    EXPECT_EQ(plan.notSwept[4].knob, "ray_weight_cutoff");
    for (const Setting& s : plan.settings) {
        ASSERT_NE(s.label.rfind("shadow_steps", 0), 0u) << s.label;
        ASSERT_NE(s.label.rfind("ao_samples", 0), 0u) << s.label;
        ASSERT_NE(s.label.rfind("max_depth", 0), 0u) << s.label;
    }
}

// The ray tree's limits are swept where a material reflects or transmits,
// the cheapest value first.
TEST(SweepPlan, RayTreeKnobsSweepScenesWithMirrorsOrGlass) {
    scene::Scene base = sceneWith(0, scene::ShadowMode::Soft);
    scene::Material glass;
    glass.name = "glass";
    glass.transparency = 0.9;
    base.materials.push_back(glass);
    SweepPlan plan = planSweep(base, parseKnobRequests({"max_depth", "ray_weight_cutoff"}));
    EXPECT_TRUE(plan.notSwept.empty());
    EXPECT_EQ(labels(plan),
              (std::vector<std::string>{"default", "max_depth=0", "max_depth=1", "max_depth=2", "max_depth=3",
                                        "max_depth=6", "ray_weight_cutoff=0.1", "ray_weight_cutoff=0.03",
                                        "ray_weight_cutoff=0.01", "ray_weight_cutoff=0.001"}));
}

TEST(SweepPlan, EpsilonModeKeepsTheThresholdAtTheCameraDistance) {
    scene::Scene base = sceneWith(0, scene::ShadowMode::Soft);
    base.render.epsilonMode = scene::EpsilonMode::Pixel;
    base.render.epsilon = 0.5;
    SweepPlan plan = planSweep(base, parseKnobRequests({"epsilon_mode"}));
    ASSERT_EQ(plan.settings.size(), 2u);
    const scene::RenderSettings& r = plan.settings[1].scene.render;
    EXPECT_EQ(r.epsilonMode, scene::EpsilonMode::Absolute);
    // 0.5 of one sub-sample's footprint at the camera's distance (6, fov 45, 36 rows, AA 1)
    EXPECT_NEAR(r.epsilon, 0.5 * 6.0 * 2.0 * std::tan(22.5 * M_PI / 180.0) / 36.0, 1e-12);
}

TEST(SweepPlan, ValuesTheFormatRejectsAreErrorsWhenGivenAndDroppedAsDefaults) {
    scene::Scene base = sceneWith(0, scene::ShadowMode::Soft);
    try {
        planSweep(base, parseKnobRequests({"max_steps=0"}));
        FAIL() << "no error";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("max_steps=0: render.max_steps"), std::string::npos) << e.what();
    }
    base.render.maxSteps = 8000;  // x2 would pass the format's limit
    SweepPlan plan = planSweep(base, parseKnobRequests({"max_steps"}));
    EXPECT_EQ(labels(plan), (std::vector<std::string>{"default", "max_steps=2000", "max_steps=4000"}));
}

TEST(TunedSetting, CombinesEachKnobsFastestValueWithinTheSlack) {
    scene::Scene base = sceneWith(4, scene::ShadowMode::Soft);
    SweepPlan plan = planSweep(base, parseKnobRequests({"max_steps=64,128", "shadow_steps=16,32", "aa=2",
                                                        "step_relaxation=1.5"}));
    ASSERT_EQ(plan.settings.size(), 7u);
    // default: 10 s at error 1.0
    std::vector<TuningCandidate> c = {{&plan.settings[0], 10, 1.0}, {&plan.settings[1], 6, 1.2},
                                      {&plan.settings[2], 8, 1.1},  {&plan.settings[3], 5, 3.0},
                                      {&plan.settings[4], 9, 1.4},  {&plan.settings[5], 20, 0.5},
                                      {&plan.settings[6], 9.5, 1.0}};
    std::optional<Setting> tuned = tunedSetting(base, c, 10, 1.0, 0.5);
    ASSERT_TRUE(tuned);
    // max_steps=64 (fastest within 1.5), shadow_steps=32 (16 is too far off), no aa (slower), relaxation
    EXPECT_EQ(tuned->label, "tuned: max_steps=64 shadow_steps=32 step_relaxation=1.5");
    EXPECT_EQ(tuned->scene.render.maxSteps, 64);
    EXPECT_EQ(tuned->scene.render.shadowSteps, 32);
    EXPECT_EQ(tuned->scene.render.aa, 1);
    EXPECT_EQ(tuned->scene.render.stepRelaxation, 1.5);
    std::optional<Setting> plain = withoutRelaxation(base, *tuned);
    ASSERT_TRUE(plain);
    EXPECT_EQ(plain->label, "tuned, plain steps: max_steps=64 shadow_steps=32");
    EXPECT_EQ(plain->scene.render.stepRelaxation, 1.0);
    EXPECT_EQ(plain->scene.render.shadowSteps, 32);
    EXPECT_FALSE(withoutRelaxation(base, *plain));
    std::optional<Setting> relaxedOnly = tunedSetting(base, c, 10, 1.0, 0.0);
    EXPECT_FALSE(withoutRelaxation(base, *relaxedOnly));  // that would be the default again
    EXPECT_EQ(tunedSetting(base, c, 10, 1.0, 0.0)->label, "tuned: step_relaxation=1.5");  // as close, faster
    EXPECT_FALSE(tunedSetting(base, c, 9, 1.0, 0.0));
}

}  // namespace
}  // namespace sdfwb::tradeoff
