// The script interpreter against a fake host: parsing errors name the line,
// commands edit through the Editor (so undo works), waits and quit rules.

#include <gtest/gtest.h>

#include <chrono>

#include "scene/scene_json.h"
#include "support/source_tree.h"
#include "ui/problems.h"
#include "ui/script.h"
#include "ui/view_camera.h"

namespace sdfwb::ui {
namespace {

struct FakeHost : ScriptHost {
    bool busy = false;
    bool quitCalled = false;
    std::vector<std::string> screenshots;
    std::vector<std::string> saved;
    Editor* editor = nullptr;

    bool idle() const override { return !busy; }
    std::string requestScreenshot(const std::filesystem::path& path) override {
        screenshots.push_back(path.string());
        return "";
    }
    std::string save(const std::filesystem::path& path) override {
        saved.push_back(path.string());
        editor->markSaved();
        return "";
    }
    std::string open(const std::filesystem::path&) override { return "cannot open in tests"; }
    void quit() override { quitCalled = true; }
    PolynomialPanelState polynomial;
    PolynomialPanelState& polynomialPanel() override { return polynomial; }
};

struct ScriptRun {
    Editor editor{scene::loadSceneFile(sdfwb::test::sourceDir() + "/scenes/default.json")};
    UiState ui;
    FakeHost host;
    ScriptStatus status = ScriptStatus::Running;
    std::string error;
    int frames = 0;

    explicit ScriptRun(const std::string& text, int maxFrames = 1000) {
        host.editor = &editor;
        ScriptRunner runner(parseScript(text, "test.txt"), "test.txt");
        while (status == ScriptStatus::Running && frames < maxFrames) {
            status = runner.step(editor, ui, host);
            ++frames;
        }
        error = runner.error();
    }
};

TEST(ScriptParseTest, UnknownCommandNamesTheLine) {
    try {
        parseScript("# comment\n\nselect root\nfly away\n", "demo.txt");
        FAIL() << "expected an error";
    } catch (const std::runtime_error& error) {
        EXPECT_EQ(std::string(error.what()).rfind("demo.txt:4: unknown command \"fly\"", 0), 0u) << error.what();
    }
}

TEST(ScriptParseTest, WrongArgumentCountNamesTheLineAndUsage) {
    try {
        parseScript("camera 1 2\n", "demo.txt");
        FAIL() << "expected an error";
    } catch (const std::runtime_error& error) {
        EXPECT_STREQ(error.what(),
                     "demo.txt:1: wrong number of arguments (usage: camera <azimuth> <elevation> <distance>)");
    }
}

TEST(ScriptParseTest, LinesOfOtherBlanksAreBlankAndBlanksSeparateWords) {
    // a lone vertical tab used to trim to itself and split into no words (fuzz_script)
    EXPECT_TRUE(parseScript("\v\n\f \t\n", "test.txt").empty());
    std::vector<ScriptCommand> commands = parseScript("select\vroot\n", "test.txt");
    ASSERT_EQ(commands.size(), 1u);
    EXPECT_EQ(commands[0].name, "select");
    EXPECT_EQ(commands[0].args, std::vector<std::string>{"root"});
}

TEST(ScriptParseTest, SetKeepsTheWholeValue) {
    auto commands = parseScript("set half_extents 1 2 3\n", "s");
    ASSERT_EQ(commands.size(), 1u);
    EXPECT_EQ(commands[0].args, (std::vector<std::string>{"half_extents", "1 2 3"}));
}

TEST(ScriptRunTest, EditsUndoAndSave) {
    ScriptRun run("select root.children[0].children[0]\n"
            "set radius 0.5\n"
            "set material blue\n"
            "undo\n"
            "set render.aa 1\n"
            "backend cpu\n"
            "camera 45 30 8\n"
            "save out.json\n"
            "quit\n");
    EXPECT_EQ(run.status, ScriptStatus::Finished) << run.error;
    const scene::Node* ball = findNode(run.editor.scene().root, {0, 0});
    EXPECT_EQ(ball->real("radius"), 0.5);
    EXPECT_EQ(ball->text("material"), "red");
    EXPECT_EQ(run.editor.scene().render.aa, 1);
    EXPECT_EQ(run.editor.scene().camera.azimuth, 45);
    EXPECT_EQ(run.editor.scene().camera.distance, 8);
    EXPECT_EQ(run.ui.backend, ViewBackend::Cpu);
    EXPECT_EQ(run.host.saved, std::vector<std::string>{"out.json"});
    EXPECT_TRUE(run.host.quitCalled);
    // the camera command is a view change, not an undo step: undo takes back render.aa
    run.editor.undo();
    EXPECT_EQ(run.editor.scene().camera.azimuth, 45);
    EXPECT_EQ(run.editor.scene().render.aa, 2);
}

TEST(ScriptRunTest, InvalidValueStopsWithTheLineAndLoaderMessage) {
    ScriptRun run("select root.children[0].children[0]\nset radius -1\nquit discard\n");
    EXPECT_EQ(run.status, ScriptStatus::Failed);
    EXPECT_EQ(run.error, "test.txt:2: set: root.children[0].children[0].radius: must be > 0 (got -1)");
    EXPECT_FALSE(run.host.quitCalled);
}

TEST(ScriptRunTest, AnExpectedRefusalReachesTheProblemsListUntilTheValueIsFixed) {
    ScriptRun run("select root.children[0].children[0]\nfails set radius -1\n");
    ASSERT_EQ(run.status, ScriptStatus::Finished) << run.error;
    updateProblems(run.ui, run.editor);
    std::vector<const Message*> open = openErrors(run.ui);
    ASSERT_EQ(open.size(), 1u);
    EXPECT_EQ(open[0]->text, "root.children[0].children[0].radius: must be > 0 (got -1)");
    EXPECT_TRUE(run.editor.setField({0, 0}, "radius", 0.5).empty());
    updateProblems(run.ui, run.editor);
    EXPECT_TRUE(openErrors(run.ui).empty());
}

TEST(ScriptRunTest, BadPathAndMissingSelection) {
    EXPECT_EQ(ScriptRun("select root.children[9]\n").error, "test.txt:1: select: root.children[9]: no such node");
    EXPECT_EQ(ScriptRun("delete\n").error, "test.txt:1: delete: no node selected");
    EXPECT_EQ(ScriptRun("add blob\n").error.rfind("test.txt:1: add: unknown node kind \"blob\"", 0), 0u);
}

TEST(ScriptRunTest, QuitRefusesUnsavedChanges) {
    ScriptRun run("add sphere\nquit\n");
    EXPECT_EQ(run.status, ScriptStatus::Failed);
    EXPECT_EQ(run.error, "test.txt:2: quit: the scene has unsaved changes (save it first, or use quit discard)");
    ScriptRun discard("add sphere\nquit discard\n");
    EXPECT_EQ(discard.status, ScriptStatus::Finished);
    EXPECT_TRUE(discard.host.quitCalled);
}

TEST(ScriptRunTest, WaitFramesAndScreenshotWaitsForIdle) {
    ScriptRun frames("wait 5\n");
    EXPECT_EQ(frames.status, ScriptStatus::Finished);
    EXPECT_GE(frames.frames, 6);

    FakeHost host;
    Editor editor;
    UiState ui;
    host.editor = &editor;
    host.busy = true;
    ScriptRunner runner(parseScript("screenshot a.png\n", "s"), "s");
    for (int i = 0; i < 10; ++i) EXPECT_EQ(runner.step(editor, ui, host), ScriptStatus::Running);
    EXPECT_TRUE(host.screenshots.empty());
    host.busy = false;
    EXPECT_EQ(runner.step(editor, ui, host), ScriptStatus::Finished);
    EXPECT_EQ(host.screenshots, std::vector<std::string>{"a.png"});
}

TEST(ScriptRunTest, WaitIdleTimesOut) {
    FakeHost host;
    Editor editor;
    UiState ui;
    host.editor = &editor;
    host.busy = true;
    ScriptRunner runner(parseScript("wait idle\n", "s"), "s");
    runner.idleTimeout = std::chrono::seconds(0);
    runner.step(editor, ui, host);
    ScriptStatus status = ScriptStatus::Running;
    for (int i = 0; i < 100 && status == ScriptStatus::Running; ++i) status = runner.step(editor, ui, host);
    EXPECT_EQ(status, ScriptStatus::Failed);
    EXPECT_EQ(runner.error().rfind("s:1: wait: still busy after 0 s", 0), 0u) << runner.error();
}

// Steps the script as frames would, waiting for the polynomial job between
// steps (an event, not a clock) where the GUI would keep drawing.
ScriptStatus runUntilDone(ScriptRunner& runner, Editor& editor, UiState& ui, FakeHost& host) {
    ScriptStatus status = ScriptStatus::Running;
    for (int frame = 0; frame < 100 && status == ScriptStatus::Running; ++frame) {
        status = runner.step(editor, ui, host);
        host.polynomial.job.wait();
    }
    return status;
}

TEST(ScriptRunTest, PolynomialCommandsImplicitizeAndAddTheSurface) {
    FakeHost host;
    Editor editor;
    UiState ui;
    host.editor = &editor;
    ScriptRunner runner(parseScript("polynomial open\n"
                                    "polynomial equations x = u*v; y = v; z = u^2\n"
                                    "polynomial order lex\n"
                                    "polynomial range v -2 2\n"
                                    "polynomial run\n"
                                    "polynomial add\n",
                                    "s"),
                        "s");
    ASSERT_EQ(runUntilDone(runner, editor, ui, host), ScriptStatus::Finished) << runner.error();
    EXPECT_TRUE(host.polynomial.open);
    EXPECT_EQ(host.polynomial.request.order, algebra::EliminationOrder::Lex);
    ASSERT_EQ(editor.scene().root.children.size(), 1u);
    const scene::Node& node = editor.scene().root.children[0];
    EXPECT_EQ(node.text("formula"), "y^2*z - x^2");
    EXPECT_NEAR(node.vec3("bounds_max").y, 2.2, 1e-9);  // v in [-2, 2], padded by 5%
}

TEST(ScriptRunTest, PolynomialCommandErrorsNameTheLine) {
    Editor editor;
    UiState ui;
    // each script on a fresh window, with the default equations
    auto failure = [&](const std::string& script) {
        FakeHost host;
        host.editor = &editor;
        ScriptRunner runner(parseScript(script, "s"), "s");
        EXPECT_EQ(runUntilDone(runner, editor, ui, host), ScriptStatus::Failed);
        return runner.error();
    };
    EXPECT_EQ(failure("polynomial equations x = t; y = sqrt(t); z = t\npolynomial run\n"),
              "s:2: polynomial: column 12: 'sqrt' is not a polynomial or rational function");
    EXPECT_EQ(failure("polynomial equations x = t; y = t^2; z = t^3\npolynomial range s 0 1\n"),
              "s:2: polynomial: the equations have no parameter \"s\"");
    EXPECT_EQ(failure("polynomial add\n").rfind("s:1: polynomial: no surface to add", 0), 0u);
    EXPECT_EQ(failure("polynomial equations x = t; y = t^2; z = t^3\npolynomial run\npolynomial add\n")
                  .rfind("s:3: polynomial: no surface to add", 0),
              0u);
    EXPECT_EQ(failure("polynomial equations x = sqrt(t); y = t; z = t\npolynomial range t 0 1\n"),
              "s:2: polynomial: column 5: 'sqrt' is not a polynomial or rational function");
    EXPECT_EQ(failure("polynomial order revlex\n").rfind("s:1: polynomial: unknown order \"revlex\"", 0), 0u);
    EXPECT_TRUE(editor.scene().root.children.empty());
}

}  // namespace
}  // namespace sdfwb::ui

namespace sdfwb::ui {
namespace {

TEST(ScriptRunTest, ViewCommandsMoveTheCameraWithoutModifyingTheScene) {
    ScriptRun run("view top\nview front\norbit 0 -200\nselect root.children[0]\nview selected\nview all\nquit\n");
    EXPECT_EQ(run.status, ScriptStatus::Finished) << run.error;  // quit: nothing unsaved
    EXPECT_FALSE(run.editor.canUndo());
    EXPECT_EQ(run.editor.scene().camera.elevation, kHomeElevation);
    EXPECT_EQ(ScriptRun("view sideways\n").error,
              "test.txt:1: view: must be front, back, right, left, top, bottom, all or selected (got sideways)");
    EXPECT_EQ(ScriptRun("view selected\n").error, "test.txt:1: view: nothing is selected");
}

}  // namespace
}  // namespace sdfwb::ui
