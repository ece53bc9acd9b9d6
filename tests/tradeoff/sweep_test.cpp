// What runSweep renders with a backend: each scene once untimed before its
// timed renders (the first render of a scene carries one-off costs that
// would otherwise be charged to the default, measured first), then every
// measured setting `repetitions` times.

#include <gtest/gtest.h>

#include "cpu/cpu_backend.h"
#include "support/scratch_folder.h"
#include "tradeoff/sweep.h"
#include "tradeoff/sweep_plan.h"

namespace sdfwb::tradeoff {
namespace {

// The CPU backend, counting its renders.
class CountingBackend : public cpu::CpuBackend {
public:
    render::RenderOutcome render(const program::Program& program, const render::RenderControl& control) override {
        ++renders;
        return cpu::CpuBackend::render(program, control);
    }
    int renders = 0;
};

TEST(Sweep, RendersEachSceneOnceUntimedBeforeItsTimedRenders) {
    test::ScratchFolder cache("sdfwb-sweep-");
    scene::Scene s;
    s.render.aoSamples = 0;
    CountingBackend backend;
    std::vector<render::Backend*> backends{&backend};
    SweepOptions options;
    options.width = 16;
    options.height = 9;
    options.repetitions = 2;
    options.cacheDir = cache.path();
    SweepResult result =
        runSweep({{"empty", s}, {"empty again", s}}, parseKnobRequests({"max_steps=64"}), backends, options);
    ASSERT_EQ(result.scenes.size(), 2u);
    int measured = 0;
    for (const SceneResult& scene : result.scenes) {
        measured += static_cast<int>(scene.results.size());
        for (const SettingResult& r : scene.results) EXPECT_EQ(r.byBackend[0].repetitionSeconds.size(), 2u);
    }
    EXPECT_GE(measured, 4);  // per scene the default and max_steps=64
    EXPECT_EQ(backend.renders, 2 + 2 * measured);
}

}  // namespace
}  // namespace sdfwb::tradeoff
