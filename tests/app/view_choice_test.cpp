// The viewport's decisions without a window (app/gui/view_choice.h): which
// image a slot shows and what it says about it, when tiles refine in place,
// and which backends render.

#include <gtest/gtest.h>

#include "app/gui/view_choice.h"

namespace sdfwb::app::gui {
namespace {

using Note = SlotView::Note;
constexpr std::uint64_t kOld = 7, kNow = 8;

SlotView choose(Source wanted, ImageContent gl, ImageContent cpu, bool interacting = false) {
    const ImageContent textures[kSources] = {gl, cpu};
    return chooseSlot(wanted, textures, kNow, interacting);
}

TEST(ViewChoice, TheWantedBackendsCurrentImageNeedsNoNote) {
    SlotView v = choose(Source::Cpu, {kNow, 2}, {kNow, 0});
    EXPECT_EQ(v.shown, Source::Cpu);
    EXPECT_EQ(v.note, Note::None);
}

TEST(ViewChoice, SwitchingBackendShowsTheOtherCurrentImageAsAStandIn) {
    // the CPU texture holds an image from many edits ago: never shown unmarked
    SlotView v = choose(Source::Cpu, {kNow, 2}, {kOld, 2});
    EXPECT_EQ(v.shown, Source::Gl);
    EXPECT_EQ(v.note, Note::StandIn);
}

TEST(ViewChoice, AnEarlierStateIsMarkedOutdatedUnlessTheUserDrags) {
    EXPECT_EQ(choose(Source::Gl, {kOld, 1}, {}).note, Note::Outdated);
    EXPECT_EQ(choose(Source::Gl, {kOld, 1}, {}).shown, Source::Gl);
    EXPECT_EQ(choose(Source::Gl, {kOld, 1}, {}, true).note, Note::None);
    // nothing of its own yet: the other backend's earlier image, marked
    SlotView v = choose(Source::Cpu, {kOld, 1}, {});
    EXPECT_EQ(v.shown, Source::Gl);
    EXPECT_EQ(v.note, Note::Outdated);
}

TEST(ViewChoice, ADragDrawsTheFreshestCompiledStateAsItsPreview) {
    constexpr std::uint64_t kDragged = 9;                       // a state compiled while the drag asks for newer ones
    EXPECT_TRUE(drawsCompiled(true, kNow, kOld, false, true));  // what the lane asked for
    EXPECT_TRUE(drawsCompiled(false, kDragged, kOld, true, true));
    // nothing newer than the texture holds, or an image the resized view no longer fits
    EXPECT_FALSE(drawsCompiled(false, kOld, kOld, true, true));
    EXPECT_FALSE(drawsCompiled(false, kDragged, kOld, true, false));
    // the drag is over: a late program of an older state waits for the current one
    EXPECT_FALSE(drawsCompiled(false, kDragged, kOld, false, true));
}

TEST(ViewChoice, NothingRenderedYetIsSaid) { EXPECT_EQ(choose(Source::Gl, {}, {}).note, Note::Empty); }

TEST(ViewChoice, TilesRefineOnlyAnImageOfTheSameState) {
    EXPECT_TRUE(refinesInPlace({kNow, 0}, kNow));   // the preview refined to full size
    EXPECT_FALSE(refinesInPlace({kOld, 2}, kNow));  // would make a patchwork of two states
    EXPECT_FALSE(refinesInPlace({}, kNow));
}

TEST(ViewChoice, TheCpuStandsInWhileTheGlProgramBuilds) {
    LanePlan building = planLanes(Source::Gl, false, false, false);
    EXPECT_TRUE(building.renders[0]);
    EXPECT_TRUE(building.renders[1]);
    EXPECT_TRUE(building.standIn);
    // as soon as the program is ready the stand-in stops, before it finishes
    LanePlan ready = planLanes(Source::Gl, false, true, false);
    EXPECT_TRUE(ready.renders[0]);
    EXPECT_FALSE(ready.renders[1]);
    EXPECT_FALSE(ready.standIn);
}

TEST(ViewChoice, AFailedGlBuildLeavesTheCpuRendering) {
    LanePlan failed = planLanes(Source::Gl, false, false, true);
    EXPECT_FALSE(failed.renders[0]);
    EXPECT_TRUE(failed.renders[1]);
    LanePlan comparing = planLanes(Source::Gl, true, true, true);
    EXPECT_FALSE(comparing.renders[0]);
    EXPECT_TRUE(comparing.renders[1]);
}

TEST(ViewChoice, CompareRendersBothAndTheCpuViewOnlyTheCpu) {
    LanePlan both = planLanes(Source::Cpu, true, false, false);
    EXPECT_TRUE(both.renders[0]);
    EXPECT_TRUE(both.renders[1]);
    EXPECT_FALSE(both.standIn);
    LanePlan cpu = planLanes(Source::Cpu, false, false, false);
    EXPECT_FALSE(cpu.renders[0]);
    EXPECT_TRUE(cpu.renders[1]);
}

TEST(ViewChoice, APreviewCostsAboutItsBudgetAtTheMeasuredPrice) {
    const double pixels = 882.0 * 704.0;
    EXPECT_EQ(previewScale(pixels, 0), kCoarsestPreview);  // nothing measured yet
    EXPECT_EQ(previewScale(pixels, 1e-9), 2);              // a cheap scene: half resolution at most
    for (double price : {1e-7, 1e-6, 1e-5}) {
        int scale = previewScale(pixels, price);
        double seconds = pixels / (scale * scale) * price;
        EXPECT_LE(seconds, kPreviewSeconds) << price;
        // the next finer scale would be over the budget
        if (scale > 2) {
            EXPECT_GT(pixels / ((scale - 1) * (scale - 1)) * price, kPreviewSeconds) << price;
        }
    }
    EXPECT_EQ(previewScale(pixels, 1e-3), kCoarsestPreview);  // the whole molecule, 0.7 ms a sample
}

// After an edit the prune grid is rebuilt while the preview evaluates the
// whole program: its price, not the pruned stage's, sizes it.
TEST(ViewChoice, APreviewWhileTheGridIsPendingIsPricedAsAWholeProgramRender) {
    EXPECT_EQ(previewSecondsPerSample(2e-5, 6e-4, true), 6e-4);
    EXPECT_EQ(previewSecondsPerSample(2e-5, 6e-4, false), 2e-5);  // after a relight the grid is there
    EXPECT_EQ(previewSecondsPerSample(2e-5, 0, true), 2e-5);      // no whole render measured yet
    // a small scene has no grid, its previews are its whole renders: the larger counts
    EXPECT_EQ(previewSecondsPerSample(3e-6, 2e-6, true), 3e-6);
}

}  // namespace
}  // namespace sdfwb::app::gui
