#pragma once
// Running the real workbench window from tests: under Xvfb (xvfb-run -a), in
// a fresh folder of the test output with its own XDG folders (so a test never
// reads or writes the user's recent files or autosave), on a GUI script.

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "image/image.h"

namespace sdfwb::test {

// Folder `name` of the test output, emptied, with config/, state/ and
// `script` as script.txt.
std::filesystem::path makeGuiFolder(const std::string& name, const std::string& script);

// The shell command that runs `sdf-workbench gui <arguments>` in `dir` under
// Xvfb with the folder's XDG folders. With `printPid`, the workbench's own
// process id is the first line of its output (to signal it, not xvfb-run).
std::string guiShellCommand(const std::filesystem::path& dir, const std::string& arguments, bool printPid = false);

// Runs `gui --script script.txt` in `dir`; the output in dir/run.log; the
// exit status expected 0 (a test failure with the log otherwise).
void runGuiScript(const std::filesystem::path& dir);

std::string readAll(const std::filesystem::path& path);

// Over the viewport of a 1280x800 screenshot (left of the side column,
// below the statistics overlay, above the status bar): the mean absolute
// difference in levels of 255, and the standard deviation of the luminance
// (near zero for a blank image).
double meanDifference(const image::Image& a, const image::Image& b);
double contrast(const image::Image& shot);

// Skips the test when no X server can start, or fails it with
// SDFWB_REQUIRE_GL=1.
class GuiTest : public ::testing::Test {
protected:
    void SetUp() override;
};

}  // namespace sdfwb::test
