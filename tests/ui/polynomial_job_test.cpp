// The polynomial panel's background job: a run on the worker thread gives the
// known equation with degree and terms, progress and Cancel never wait for the
// worker, errors come back as one line, and the outcome becomes a
// valid `polynomial` node added through the editor (undoable).

#include <gtest/gtest.h>

#include "scene/scene_json.h"
#include "ui/polynomial_panel.h"

namespace sdfwb::ui {
namespace {

PolynomialOutcome runToEnd(PolynomialRequest request) {
    PolynomialJob job;
    job.start(std::move(request));
    job.wait();
    EXPECT_FALSE(job.running());
    return job.outcome().value();
}

TEST(PolynomialJob, WhitneyUmbrellaGivesItsEquation) {
    PolynomialOutcome o = runToEnd({});  // the default: x = u*v; y = v; z = u^2
    ASSERT_TRUE(o.ok) << o.message;
    ASSERT_TRUE(o.isSurface());
    EXPECT_EQ(o.degree, 3u);
    EXPECT_EQ(o.terms, 2u);
    EXPECT_NE(o.message.find("degree 3, 2 terms"), std::string::npos) << o.message;
    EXPECT_FALSE(o.bounds.has_value());
}

TEST(PolynomialJob, ParseErrorsComeBackAsOneLine) {
    PolynomialOutcome o = runToEnd({.equations = "x = u*; y = v; z = u"});
    EXPECT_FALSE(o.ok);
    EXPECT_NE(o.message.find("column"), std::string::npos) << o.message;
    EXPECT_EQ(o.message.find('\n'), std::string::npos);
}

TEST(PolynomialJob, ParameterRangeGivesSampledBounds) {
    PolynomialOutcome o = runToEnd({.parameterRange = std::pair{-1.0, 1.0}});
    ASSERT_TRUE(o.ok) << o.message;
    ASSERT_TRUE(o.bounds.has_value());
    // x = u*v and y = v in [-1, 1], z = u^2 in [0, 1]; padded by 5%
    EXPECT_NEAR(o.bounds->first.x, -1.1, 1e-9);
    EXPECT_NEAR(o.bounds->second.y, 1.1, 1e-9);
    EXPECT_NEAR(o.bounds->first.z, -0.05, 1e-9);
    EXPECT_NEAR(o.bounds->second.z, 1.05, 1e-9);
}

// Cancel and progress only touch the shared state: they return at once while
// the worker runs, and the run ends either completed or "cancelled". (A long
// input is not used: the engine's modular phase does not poll the budget yet,
// so e.g. the Moebius strip with half-angle ignores Cancel; see the report.)
TEST(PolynomialJob, CancelAndProgressNeverWaitForTheWorker) {
    PolynomialJob job;
    job.start({.equations = "x = u^3 - v; y = u*v^2 + u; z = v^3 - u^2*v", .timeLimitSeconds = 30});
    PolynomialProgress p = job.progress();
    EXPECT_GE(p.elapsedSeconds, 0.0);
    job.cancel();
    job.wait();
    EXPECT_FALSE(job.running());
    PolynomialOutcome o = job.outcome().value();
    EXPECT_TRUE(o.ok || o.message.find("cancel") != std::string::npos) << o.message;
}

TEST(PolynomialJob, OutcomeBecomesAValidPolynomialNode) {
    PolynomialOutcome o = runToEnd({.parameterRange = std::pair{-1.0, 1.0}});
    ASSERT_TRUE(o.isSurface());
    scene::Scene start;
    Editor editor(start);
    UiState ui;
    ASSERT_TRUE(addPolynomialNode(editor, ui, o).empty());
    ASSERT_EQ(editor.scene().root.children.size(), 1u);
    const scene::Node& node = editor.scene().root.children[0];
    EXPECT_EQ(node.kind, scene::NodeKind::Polynomial);
    EXPECT_EQ(node.text("formula"), o.generators[0]);
    EXPECT_EQ(node.vec3("bounds_min"), o.bounds->first);
    nlohmann::ordered_json json = scene::sceneToJson(editor.scene());
    EXPECT_EQ(json["root"]["children"][0]["kind"], "polynomial");
    EXPECT_EQ(json["root"]["children"][0]["formula"], o.generators[0]);
    ASSERT_TRUE(editor.undo());
    EXPECT_TRUE(editor.scene().root.children.empty());
}

}  // namespace
}  // namespace sdfwb::ui
