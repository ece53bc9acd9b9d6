// The workbench window against hostile input (issue 15), run for real under
// Xvfb on GUI scripts: files that do not load (nested too deep, a formula
// nested too deep, cut short) and values the loader refuses are errors shown
// to the user that leave the scene and its undo history as they were; a
// scene whose shader would compile for minutes is refused by the GL viewport
// with a message (the CPU backend stands in), never compiled; the autosave of a window killed
// with SIGKILL is restored on the next start.
// Skipped when no X server can start, unless SDFWB_REQUIRE_GL=1.

#include <gtest/gtest.h>

#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "scene/scene_json.h"
#include "support/source_tree.h"
#include "ui/gui_run.h"
#include "ui/node_path.h"

namespace sdfwb::ui {
namespace {

namespace fs = std::filesystem;
using GuiHostileTest = test::GuiTest;

constexpr const char* kHeader = R"({"format": "sdf-workbench-scene", "version": 1, )";

std::size_t occurrences(const std::string& text, const std::string& part) {
    std::size_t count = 0;
    for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++count;
    return count;
}

// The default scene at AA 1 with the ball's radius 0.4: the state the
// scripts below leave after their edits.
scene::Scene editedDefaultScene() {
    scene::Scene expected = scene::loadSceneFile(fs::path(sdfwb::test::sourceDir()) / "scenes/default.json");
    expected.render.aa = 1;
    findNode(expected.root, {0, 0})->set("radius", 0.4);
    return expected;
}

TEST_F(GuiHostileTest, FilesAndValuesThatDoNotLoadKeepTheSceneAndItsUndoHistory) {
    const std::string deepParentheses = std::string(100000, '(') + "length(p) - 1" + std::string(100000, ')');
    const std::string script = "set render.aa 1\n"
                               "select root.children[0].children[0]\n"
                               "set radius 0.4\n"
                               "fails open deep.json\n"
                               "fails open deep_formula.json\n"
                               "fails open truncated.json\n"
                               "fails open missing.json\n"
                               "fails set radius -1\n"
                               "add sdf\n"
                               "fails set formula " + deepParentheses + "\n"
                               "fails set formula 1/0\n"
                               "fails set formula 0^-1\n"
                               "fails set formula x^99999999999999999999\n"
                               "undo\n"
                               "undo\n"
                               "redo\n"
                               "save kept.json\n"
                               "quit\n";
    fs::path dir = test::makeGuiFolder("gui_hostile_files", script);
    std::ofstream(dir / "deep.json") << kHeader << R"("name": )" << std::string(200000, '[')
                                     << std::string(200000, ']') << R"(, "root": {"kind": "sphere"}})";
    std::ofstream(dir / "deep_formula.json") << kHeader << R"("root": {"kind": "sdf", "formula": ")"
                                             << deepParentheses << R"("}})";
    std::string whole = test::readAll(fs::path(sdfwb::test::sourceDir()) / "scenes/default.json");
    std::ofstream(dir / "truncated.json") << whole.substr(0, whole.size() / 2);
    test::runGuiScript(dir);
    ASSERT_FALSE(HasFailure());

    // every refusal reached the user, each as one message
    std::string log = test::readAll(dir / "run.log");
    EXPECT_EQ(occurrences(log, "(expected)"), 9u) << log.substr(0, 4000);
    EXPECT_NE(log.find("nested deeper than"), std::string::npos) << log.substr(0, 4000);
    EXPECT_NE(log.find("nests deeper than"), std::string::npos) << log.substr(0, 4000);
    EXPECT_LT(log.size(), 20000u) << "messages quote hostile input whole";
    // the two undos and the redo found the history intact: the edits, no sdf node
    EXPECT_EQ(scene::loadSceneFile(dir / "kept.json"), editedDefaultScene());
}

// The GL build is refused at once (a message in the log, the CPU backend
// standing in), so frames go on being drawn; nothing waits for the CPU's
// image, which a shared test machine may take minutes to finish. (An
// intersection: a union of translated spheres compiles to one fold loop,
// gl/fold_run.h, and fits.)
TEST_F(GuiHostileTest, ASceneOverTheShaderBoundIsRefusedByTheGlViewportWithAMessage) {
    std::string children;
    for (int i = 0; i < 600; ++i) {
        children += std::string(i ? ", " : "") + R"({"kind": "translate", "offset": [)" +
                    std::to_string(-1.8 + (i % 25) * 0.15) + ", 0.3, " + std::to_string(-1.8 + (i / 25) * 0.15) +
                    R"(], "children": [{"kind": "sphere", "radius": 0.05}]})";
    }
    fs::path dir = test::makeGuiFolder("gui_hostile_wide", "open wide.json\nwait 30\nquit\n");
    std::ofstream(dir / "wide.json") << kHeader << R"("root": {"kind": "intersection", "children": [)" << children << "]}}";
    test::runGuiScript(dir);
    ASSERT_FALSE(HasFailure());
    std::string log = test::readAll(dir / "run.log");
    EXPECT_NE(log.find("the scene makes a shader of 1799 statements"), std::string::npos) << log;
    EXPECT_NE(log.find("the CPU backend still works"), std::string::npos) << log;
    EXPECT_EQ(log.find("backend: GL backend"), std::string::npos) << "the backend named twice: " << log;
}

TEST_F(GuiHostileTest, TheAutosaveOfAKilledWindowIsRestoredOnTheNextStart) {
    fs::path dir = test::makeGuiFolder("gui_hostile_autosave", "set render.aa 1\n"
                                                               "select root.children[0].children[0]\n"
                                                               "set radius 0.4\n"
                                                               "autosave\n");
    const fs::path autosave = dir / "state/sdf-workbench/autosave.json";
    fs::copy_file(fs::path(sdfwb::test::sourceDir()) / "scenes/default.json", dir / "scene.json");
    // the script ends with the window open and the edit unsaved; the window
    // is killed once it says it autosaved
    FILE* output = ::popen((test::guiShellCommand(dir, "scene.json --script script.txt", true) + " 2>&1").c_str(), "r");
    ASSERT_NE(output, nullptr);
    std::string lines;
    char line[4096];
    long pid = 0;
    bool autosaved = false;
    while (!autosaved && std::fgets(line, sizeof line, output)) {
        lines += line;
        if (pid == 0) pid = std::strtol(line, nullptr, 10);
        autosaved = std::string(line).find("autosaved to") != std::string::npos;
    }
    if (autosaved && pid > 0) ::kill(static_cast<pid_t>(pid), SIGKILL);
    while (std::fgets(line, sizeof line, output)) lines += line;
    ::pclose(output);
    ASSERT_TRUE(autosaved) << lines;
    ASSERT_TRUE(fs::exists(autosave)) << lines;

    std::ofstream(dir / "script.txt") << "restore\nsave recovered.json\nquit\n";
    test::runGuiScript(dir);
    ASSERT_FALSE(HasFailure());
    EXPECT_NE(
        test::readAll(dir / "run.log").find("restored unsaved work of " + fs::absolute(dir / "scene.json").string()),
        std::string::npos)
        << "the work comes back as the file's it was opened from: " << test::readAll(dir / "run.log");
    EXPECT_EQ(scene::loadSceneFile(dir / "recovered.json"), editedDefaultScene());
    EXPECT_FALSE(fs::exists(autosave)) << "saving the restored work keeps the autosave";
}

TEST_F(GuiHostileTest, RestoringWithoutAnAutosaveIsAnError) {
    fs::path dir = test::makeGuiFolder("gui_hostile_no_autosave", "fails restore\nquit\n");
    test::runGuiScript(dir);
    EXPECT_NE(test::readAll(dir / "run.log").find("no autosave at"), std::string::npos);
}

}  // namespace
}  // namespace sdfwb::ui
