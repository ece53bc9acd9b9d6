// The CPU backend behind the backend contract: a progressive render gives the
// frame of one render() call, its tiles cover the frame once, and the
// contract's defaults (nothing to build, always ready) hold.

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <vector>

#include "cpu/cpu_backend.h"
#include "program/compile_scene.h"
#include "scene/scene_json.h"
#include "support/region_check.h"
#include "support/source_tree.h"

namespace sdfwb {
namespace {

program::Program smallDefault() {
    scene::Scene s = scene::loadSceneFile(sdfwb::test::sourceDir() + "/scenes/default.json");
    return program::compileScene(s, {50, 30, 2});
}

TEST(CpuBackend, ARegionHoldsTheWholeFramesPixelsAndNothingElse) {
    cpu::CpuBackend backend;
    program::Program p = smallDefault();
    render::RenderOutcome whole = backend.render(p, {});
    const render::TileRect region{7, 5, 23, 17};
    test::expectRegionOfFrame(whole.frame, backend.render(p, {.tileSize = 8, .region = region}).frame, region);
    std::unique_ptr<render::ProgressiveRender> progressive =
        backend.startProgressive(p, {.tileSize = 8, .region = render::TileRect{-10, 20, 30, 30}});
    while (!progressive->done()) progressive->advance(0);
    test::expectRegionOfFrame(whole.frame, progressive->frame(), {0, 20, 20, 10});  // clipped to 50x30
}

TEST(CpuBackend, ProgressiveRenderGivesTheFrameOfOneRender) {
    cpu::CpuBackend backend;
    program::Program p = smallDefault();
    render::RenderOutcome whole = backend.render(p, {});
    std::unique_ptr<render::ProgressiveRender> progressive = backend.startProgressive(p, {.tileSize = 8});
    std::vector<int> covered(static_cast<size_t>(p.width) * p.height, 0);
    auto collect = [&] {
        for (const render::TileRect& t : progressive->advance(0)) {
            for (int y = t.y; y < t.y + t.h; ++y) {
                for (int x = t.x; x < t.x + t.w; ++x) ++covered[static_cast<size_t>(y) * p.width + x];
            }
        }
    };
    // the render runs on the backend's job queue; advance() only collects tiles
    while (!progressive->done()) collect();
    EXPECT_DOUBLE_EQ(progressive->progress(), 1.0);
    EXPECT_EQ(std::count(covered.begin(), covered.end(), 1), p.width * p.height);
    EXPECT_EQ(progressive->frame().color.rgb, whole.frame.color.rgb);
    EXPECT_EQ(progressive->frame().steps, whole.frame.steps);
    EXPECT_EQ(progressive->frame().depth, whole.frame.depth);
}

TEST(CpuBackend, NeedsNoBuildAndIsAlwaysReady) {
    cpu::CpuBackend backend;
    program::Program p = smallDefault();
    backend.prepare(p);
    EXPECT_TRUE(backend.readiness(p).ready);
    EXPECT_TRUE(backend.buildsIdle());
    EXPECT_EQ(backend.builds(), 0);
    EXPECT_EQ(backend.name(), "cpu");
}

TEST(CpuBackend, ACancelledRenderHasNoFrame) {
    cpu::CpuBackend backend;
    std::atomic<bool> cancel{true};
    render::RenderOutcome outcome = backend.render(smallDefault(), {.cancel = &cancel});
    EXPECT_TRUE(outcome.cancelled);
    EXPECT_EQ(outcome.frame.color.width, 0);
}

TEST(CpuBackend, AnAbandonedProgressiveRenderStopsWithoutWaiting) {
    cpu::CpuBackend backend;
    program::Program p = smallDefault();
    backend.startProgressive(p, {.tileSize = 4}).reset();  // cancelled on destruction
    // the queue goes on: the next render completes
    std::unique_ptr<render::ProgressiveRender> next = backend.startProgressive(p, {});
    while (!next->done()) next->advance(0);
    EXPECT_EQ(next->frame().color.rgb, backend.render(p, {}).frame.color.rgb);
}

}  // namespace
}  // namespace sdfwb
