// The polynomial panel's background job: a run on the worker thread gives the
// known equation with degree and terms, progress and Cancel never wait for the
// worker, errors come back as one line, and the outcome becomes a
// valid `polynomial` node added through the editor (undoable).

#include <gtest/gtest.h>

#include <numbers>
#include <stdexcept>

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

PolynomialRequest request(std::string equations, std::vector<ParameterRange> ranges = {}) {
    PolynomialRequest r;
    r.equations = std::move(equations);
    r.parameterRanges = std::move(ranges);
    return r;
}

TEST(PolynomialJob, ParseErrorsComeBackAsOneLine) {
    PolynomialOutcome o = runToEnd(request("x = u*; y = v; z = u"));
    EXPECT_FALSE(o.ok);
    EXPECT_NE(o.message.find("column"), std::string::npos) << o.message;
    EXPECT_EQ(o.message.find('\n'), std::string::npos);
}

TEST(PolynomialJob, EachParameterRangeShapesTheSampledBounds) {
    PolynomialOutcome o = runToEnd(request("x = u*v; y = v; z = u^2", {{"v", -2, 2}, {"u", -1, 1}}));
    ASSERT_TRUE(o.ok) << o.message;
    ASSERT_TRUE(o.bounds.has_value());
    // x = u*v and y = v in [-2, 2], z = u^2 in [0, 1]; padded by 5%
    EXPECT_NEAR(o.bounds->first.x, -2.2, 1e-9);
    EXPECT_NEAR(o.bounds->second.y, 2.2, 1e-9);
    EXPECT_NEAR(o.bounds->first.z, -0.05, 1e-9);
    EXPECT_NEAR(o.bounds->second.z, 1.05, 1e-9);
    EXPECT_THROW(sampledBounds("x = u*v; y = v; z = u^2", std::vector<ParameterRange>{{"u", 0, 1}}),
                 std::invalid_argument);
}

TEST(PolynomialJob, ParametersGetRangesByKind) {
    // angles run over a full turn, other parameters over [-1, 1]
    std::vector<ParameterRange> ranges = parameterRanges("x = (2 + cos(v))*cos(u); y = (2 + cos(v))*sin(u); z = w*sin(v)");
    ASSERT_EQ(ranges.size(), 3u);
    EXPECT_EQ(ranges[0].name, "v");
    EXPECT_EQ(ranges[1].name, "u");
    EXPECT_EQ(ranges[2], (ParameterRange{"w", -1, 1}));
    EXPECT_DOUBLE_EQ(ranges[0].max, 2 * std::numbers::pi);
    EXPECT_DOUBLE_EQ(ranges[1].min, 0);
    // the Moebius strip's cos(u/2) repeats after 4π
    std::vector<ParameterRange> half = parameterRanges("x = cos(u/2); y = sin(u); z = v");
    EXPECT_DOUBLE_EQ(half[0].max, 4 * std::numbers::pi);
    // a range the user gave is kept while its parameter stays, in the same role
    std::vector<ParameterRange> edited{{"w", 0, 3}, {"gone", 5, 6}, {"u", 0, 1, true}, {"v", 2, 3}};
    std::vector<ParameterRange> kept = parameterRanges("x = w; y = w^2 + u; z = t*cos(v)", edited);
    EXPECT_EQ(kept, (std::vector<ParameterRange>{
                        {"w", 0, 3}, {"u", -1, 1}, {"t", -1, 1}, {"v", 0, 2 * std::numbers::pi, true}}));
}

TEST(PolynomialPanel, ReadsEquationsAsTheyAreTypedAndRunsInTheChosenOrder) {
    PolynomialPanelState state;
    state.request.equations = "x = t; y = t^2; z = sqrt(t)";
    readParameters(state);
    EXPECT_NE(state.problem.find("column 21"), std::string::npos) << state.problem;
    state.request.equations = "x = t; y = t^2; z = t^3";
    readParameters(state);
    EXPECT_EQ(state.problem, "");
    ASSERT_EQ(state.ranges, (std::vector<ParameterRange>{{"t", -1, 1}}));
    state.ranges[0].max = 2;
    state.request.order = algebra::EliminationOrder::Lex;
    runPolynomial(state);
    state.job.wait();
    PolynomialOutcome o = state.job.outcome().value();
    ASSERT_TRUE(o.ok) << o.message;
    // a curve: its lex basis, and no node to add
    EXPECT_EQ(o.generators, (std::vector<std::string>{"y^3 - z^2", "x*z - y^2", "x*y - z", "x^2 - y"}));
    EXPECT_FALSE(o.isSurface());
    ASSERT_TRUE(o.bounds.has_value());
    EXPECT_NEAR(o.bounds->second.z, 8 + 0.05 * 9, 1e-9);  // t^3 over [-1, 2]
}

// The result shown belongs to the equations as run: edited after Run, it is
// outdated (the panel says so) until Run again.
TEST(PolynomialPanel, AResultIsOutdatedOnceTheEquationsChange) {
    PolynomialPanelState state;
    state.request.equations = "x = u*v; y = v; z = u^2";
    readParameters(state);
    runPolynomial(state);
    state.job.wait();
    EXPECT_TRUE(resultIsCurrent(state));
    state.request.equations = "x = u*v; y = v; z = u^3";
    EXPECT_FALSE(resultIsCurrent(state));
    state.request.equations = "x = u*v; y = v; z = u^2";
    state.request.order = algebra::EliminationOrder::Lex;
    EXPECT_FALSE(resultIsCurrent(state)) << "another order is another run";
    runPolynomial(state);
    state.job.wait();
    EXPECT_TRUE(resultIsCurrent(state));
}

// Cancel and progress only touch the shared state: they return at once while
// the worker runs. A cancel right after the start stops a computation far
// longer than the moment between them at its first safe point.
TEST(PolynomialJob, CancelAndProgressNeverWaitForTheWorker) {
    PolynomialJob job;
    PolynomialRequest hard = request("x = u^3 - v; y = u*v^2 + u; z = v^3 - u^2*v");
    hard.timeLimitSeconds = 30;
    job.start(hard);
    EXPECT_TRUE(job.running() || job.outcome().has_value());
    job.progress();
    job.cancel();
    job.wait();
    EXPECT_FALSE(job.running());
    PolynomialOutcome o = job.outcome().value();
    EXPECT_FALSE(o.ok);
    EXPECT_NE(o.message.find("cancel"), std::string::npos) << o.message;
}

// A newer start supersedes a running computation: only its result is kept.
TEST(PolynomialJob, ANewStartSupersedesTheRunningOne) {
    PolynomialJob job;
    PolynomialRequest hard = request("x = u^3 - v; y = u*v^2 + u; z = v^3 - u^2*v");
    hard.timeLimitSeconds = 30;
    job.start(hard);
    job.start(request("x = u*v; y = v; z = u^2"));
    job.wait();
    PolynomialOutcome o = job.outcome().value();
    ASSERT_TRUE(o.ok) << o.message;
    EXPECT_EQ(o.generators, std::vector<std::string>{"y^2*z - x^2"});
}

// The equations are read in the background: the UI is never held up by a
// conversion that expands a large power, and only the newest text counts.
TEST(ParameterCheck, ReadsOffTheUiThreadAndKeepsOnlyTheNewestText) {
    PolynomialPanelState state;
    state.request.equations = "x = (u+v+1)^60; y = v; z = u";
    checkParameters(state);  // returns at once
    state.request.equations = "x = u; y = v; z = u*v + w";
    checkParameters(state);
    readParameters(state);
    EXPECT_TRUE(parametersCurrent(state));
    EXPECT_EQ(state.problem, "");
    ASSERT_EQ(state.ranges.size(), 3u);
    EXPECT_EQ(state.ranges[2].name, "w");
}

TEST(PolynomialJob, OutcomeBecomesAValidPolynomialNode) {
    PolynomialOutcome o = runToEnd(request("x = u*v; y = v; z = u^2", {{"u", -1, 1}, {"v", -1, 1}}));
    ASSERT_TRUE(o.isSurface());
    scene::Scene start;
    Editor editor(start);
    UiState ui;
    ASSERT_TRUE(addPolynomialNode(editor, ui, o, 0.02).empty());
    ASSERT_EQ(editor.scene().root.children.size(), 1u);
    const scene::Node& node = editor.scene().root.children[0];
    EXPECT_EQ(node.kind, scene::NodeKind::Polynomial);
    EXPECT_EQ(node.text("formula"), o.generators[0]);
    EXPECT_EQ(node.vec3("bounds_min"), o.bounds->first);
    EXPECT_EQ(node.real("sheet_thickness"), 0.02);
    nlohmann::ordered_json json = scene::sceneToJson(editor.scene());
    EXPECT_EQ(json["root"]["children"][0]["kind"], "polynomial");
    EXPECT_EQ(json["root"]["children"][0]["formula"], o.generators[0]);
    ASSERT_TRUE(editor.undo());
    EXPECT_TRUE(editor.scene().root.children.empty());
}

}  // namespace
}  // namespace sdfwb::ui
