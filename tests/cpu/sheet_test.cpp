// Implicit surfaces drawn as sheets: where |F| / |grad F| overestimates the
// distance, a step of up to max_step jumped over the sheet (the Moebius
// strip's fold showed stripes of holes). Sheet steps are capped at the
// sheet's thickness, so the live march covers what tiny steps cover.

#include <gtest/gtest.h>

#include <vector>

#include "cpu/cpu_renderer.h"
#include "program/compile_scene.h"
#include "scene/scene_json.h"

namespace sdfwb {
namespace {

std::vector<float> coverage(scene::Scene s) {
    s.render.width = 240;
    s.render.height = 135;
    s.render.aa = 1;
    s.render.shadows = scene::ShadowMode::None;
    s.render.aoSamples = 0;
    // a tenth of a pixel: tiny steps must stay above the hit epsilon
    s.render.epsilon = 0.1;
    return cpu::renderCpu(program::compileScene(s)).frame.coverage;
}

TEST(ImplicitSheet, CoversWhatTinyStepsCover) {
    scene::Scene live = scene::loadSceneFile(SDFWB_SOURCE_DIR "/scenes/hard/moebius_sheet.json");
    ASSERT_GT(live.root.real("sheet_thickness"), 0);
    scene::Scene tiny = live;
    tiny.root.set("max_step", 0.004);
    tiny.render.maxSteps = 8192;
    std::vector<float> a = coverage(live), b = coverage(tiny);
    size_t hits = 0, holes = 0, extra = 0;
    for (size_t i = 0; i < a.size(); ++i) {
        hits += b[i] > 0.5f;
        holes += b[i] > 0.5f && a[i] < 0.5f;
        extra += b[i] < 0.5f && a[i] > 0.5f;
    }
    ASSERT_GT(hits, a.size() / 4);
    // silhouette pixels may differ; the stripes were hundreds of pixels
    EXPECT_LE(holes, hits / 1000) << holes << " holes of " << hits << " hits";
    EXPECT_LE(extra, hits / 1000) << extra << " extra hits";
}

}  // namespace
}  // namespace sdfwb
