// The command line as a hostile user or a broken pipeline meets it: outputs
// that would replace inputs, full disks, kills in the middle of a write,
// arguments out of range, inputs nested too deep. Nothing crashes, nothing is
// lost, and every error is one line with exit status 2.

#include <csignal>
#include <filesystem>
#include <fstream>
#include <iterator>

#include <sys/stat.h>

#include <gtest/gtest.h>

#include "cli_process.h"
#include "support/sanitizers.h"
#include "support/source_tree.h"

namespace {

using sdfwb::test::Cli;
using sdfwb::test::ProcessResult;
using sdfwb::test::run;
namespace fs = std::filesystem;

std::string contentOf(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

const std::string kSphereScene =
    R"({"format": "sdf-workbench-scene", "version": 1, "root": {"kind": "sphere"}})";

TEST_F(Cli, NoOutputMayReplaceAnInputOrAnotherOutput) {
    fs::path scene = path("scene.png"), image = path("image.png");
    std::ofstream(scene) << kSphereScene;
    ProcessResult r = run("render " + scene.string() + " -o " + scene.string() + " --size 8x8");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(r.output, "sdf-workbench render: -o " + scene.string() + " is the same file as the scene " +
                            scene.string() + " (an output may not replace an input or another output)\n");
    ProcessResult heat = run("render " + scene.string() + " -o " + image.string() + " --heat " +
                             path("./image.png").string() + " --size 8x8");
    EXPECT_EQ(heat.exitCode, 2);
    EXPECT_NE(heat.output.find("--heat"), std::string::npos) << heat.output;
    ProcessResult shader = run("render " + scene.string() + " -o " + image.string() + " --backend gl --dump-shader " +
                               scene.string() + " --size 8x8");
    EXPECT_EQ(shader.exitCode, 2);
    EXPECT_NE(shader.output.find("--dump-shader"), std::string::npos) << shader.output;
    EXPECT_EQ(contentOf(scene), kSphereScene);
    EXPECT_FALSE(fs::exists(image));
}

TEST_F(Cli, ArgumentsAreCheckedBeforeAnyWork) {
    ProcessResult dump = run("render -o " + path("a.png").string() + " --dump-shader " + path("a.frag").string());
    EXPECT_EQ(dump.exitCode, 2);
    EXPECT_EQ(dump.output, "sdf-workbench render: --dump-shader needs --backend gl (the cpu backend runs no shader)\n");
    ProcessResult report =
        run(std::string("parity ") + sdfwb::test::sourceDir() + "/scenes/default.json --report /nonexistent/x.md");
    EXPECT_EQ(report.exitCode, 2);
    EXPECT_EQ(report.output, "sdf-workbench parity: cannot write /nonexistent/x.md: folder /nonexistent does not exist\n");
    ProcessResult screenshot = run("gui --screenshot /nonexistent/s.png");
    EXPECT_EQ(screenshot.exitCode, 2);
    EXPECT_NE(screenshot.output.find("cannot write /nonexistent/s.png"), std::string::npos) << screenshot.output;
    ProcessResult extension = run("gui --screenshot " + path("s.gif").string());
    EXPECT_EQ(extension.exitCode, 2);
    EXPECT_NE(extension.output.find("unknown image format '.gif'"), std::string::npos) << extension.output;
    ProcessResult fail = run(std::string("compare ") + sdfwb::test::sourceDir() + "/tests/data/default_160x90.png " +
                             sdfwb::test::sourceDir() + "/tests/data/default_160x90.png --fail -1");
    EXPECT_EQ(fail.exitCode, 2);
    EXPECT_NE(fail.output.find("--fail"), std::string::npos) << fail.output;
    ProcessResult size = run("render -o " + path("b.png").string() + " --size 0x5");
    EXPECT_EQ(size.exitCode, 2);
    EXPECT_EQ(filesInFolder(), 0u);
}

TEST_F(Cli, ImageSizesAreCheckedAgainstMemoryBeforeAllocating) {
    // 4 GB of address space: the check must refuse, not std::bad_alloc halfway
    // (AddressSanitizer's shadow memory alone needs more address space)
    const std::string limit = sdfwb::test::kAddressSanitizer ? "" : "ulimit -v 4000000;";
    ProcessResult r = run("render -o " + path("huge.exr").string() + " --size 16384x16384", limit);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.output.find("the image is 16384x16384 pixels: rendering it needs about 34.4 GB"), std::string::npos)
        << r.output;
    EXPECT_EQ(filesInFolder(), 0u);
}

TEST_F(Cli, ThreadCountsAboveTheMachineAreClampedWithAMessage) {
    ProcessResult r = run("render -o " + path("t.png").string() + " --size 8x8 --threads 1000");
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("--threads 1000: this machine runs"), std::string::npos) << r.output;
}

TEST_F(Cli, OverwritesKeepPermissionsAndWriteThroughSymbolicLinks) {
    fs::path image = path("kept.png"), target = path("target.png"), link = path("link.png");
    ASSERT_EQ(run("render -o " + image.string() + " --size 8x8").exitCode, 0);
    ::chmod(image.c_str(), 0600);
    ASSERT_EQ(run("render -o " + image.string() + " --size 9x9").exitCode, 0);
    EXPECT_EQ(fs::status(image).permissions() & fs::perms::all, fs::perms::owner_read | fs::perms::owner_write);
    ASSERT_EQ(run("render -o " + target.string() + " --size 8x8").exitCode, 0);
    fs::create_symlink(target.filename(), link);
    ASSERT_EQ(run("render -o " + link.string() + " --size 10x10").exitCode, 0);
    EXPECT_TRUE(fs::is_symlink(link));
    EXPECT_GT(fs::file_size(target), 0u);
    EXPECT_EQ(filesInFolder(), 3u);
}

// A full disk, simulated by a file-size limit (SIGXFSZ ignored, so writes fail
// with EFBIG as they would with ENOSPC): the old file stays, nothing is left.
TEST_F(Cli, AFullDiskKeepsThePreviousFileForEveryFormat) {
    for (const char* extension : {".png", ".jpg", ".tif", ".exr"}) {
        SCOPED_TRACE(extension);
        fs::path image = path(std::string("full") + extension);
        ASSERT_EQ(run("render -o " + image.string() + " --size 16x16").exitCode, 0);
        const std::string before = contentOf(image);
        ProcessResult r = run("render -o " + image.string() + " --size 160x120", "trap '' XFSZ; ulimit -f 2;");
        EXPECT_EQ(r.exitCode, 2) << r.output;
        EXPECT_NE(r.output.find("cannot write " + image.string()), std::string::npos) << r.output;
        EXPECT_EQ(contentOf(image), before);
        EXPECT_EQ(filesInFolder(), 1u);
        fs::remove(image);
    }
}

// Killed in the middle of writing (the moment its temporary file appears):
// SIGTERM removes the temporary and ends with the signal's status; after
// SIGKILL the next write to the same file removes the leftover.
TEST_F(Cli, KillsDuringAWriteLeaveThePreviousFileAndNoTemporary) {
    fs::path image = path("killed.exr");
    ASSERT_EQ(run("render -o " + image.string() + " --size 16x16").exitCode, 0);
    const std::string before = contentOf(image);
    for (int signal : {SIGTERM, SIGINT, SIGKILL}) {
        SCOPED_TRACE(signal);
        pid_t pid = sdfwb::test::start({"render", "-o", image.string(), "--size", "800x600", "--aa", "1"});
        std::string temporary = sdfwb::test::waitForFileCreated(folder_, ".tmp-");
        ::kill(pid, signal);
        EXPECT_EQ(sdfwb::test::waitFor(pid), 128 + signal);
        EXPECT_EQ(contentOf(image), before);
        EXPECT_EQ(fs::exists(path(temporary)), signal == SIGKILL) << temporary;
    }
    ASSERT_EQ(run("render -o " + image.string() + " --size 16x16").exitCode, 0);
    EXPECT_EQ(filesInFolder(), 1u);
}

TEST_F(Cli, TimeoutsArePositiveAndFiniteOrNone) {
    for (const char* value : {"nan", "inf", "-1", "0", "abc"}) {
        ProcessResult r = run(std::string("groebner \"x^2 - y\" --vars x,y --timeout ") + value);
        EXPECT_EQ(r.exitCode, 2) << value;
        EXPECT_NE(r.output.find("must be a positive number of seconds or 'none'"), std::string::npos) << r.output;
    }
    EXPECT_EQ(run("groebner \"x^2 - y\" --vars x,y --timeout none").exitCode, 0);
    EXPECT_EQ(run("groebner \"x^2 - y\" --vars x,y --timeout 0.5").exitCode, 0);
}

TEST_F(Cli, APolynomialStartingWithAMinusIsAFormulaNotAnOption) {
    ProcessResult r = run("groebner \"-x^2 + y; x*y - 1\" --vars x,y --order lex");
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("2 polynomials"), std::string::npos) << r.output;
    EXPECT_EQ(run("implicitize \"x = -u^2; y = v; z = u\" --timeout 30").exitCode, 0);
}

TEST_F(Cli, ExpansionAndExponentLimitsAreErrorsNotHangsOrWrongAnswers) {
    ProcessResult wrap = run("groebner \"(x^65536)^65536 - 2\" --vars x");
    EXPECT_EQ(wrap.exitCode, 2);
    EXPECT_NE(wrap.output.find("would have degree"), std::string::npos) << wrap.output;
    ProcessResult expand = run("groebner \"(x+y+1)^600\" --vars x,y --timeout 2");
    EXPECT_EQ(expand.exitCode, 2);
    EXPECT_NE(expand.output.find("too large to expand exactly"), std::string::npos) << expand.output;
    ProcessResult literal = run("implicitize \"x = " + std::string(5000, '9') + "*u; y = v; z = u\"");
    EXPECT_EQ(literal.exitCode, 2);
    EXPECT_NE(literal.output.find("a number of 5000 digits"), std::string::npos) << literal.output;
}

TEST_F(Cli, DeeplyNestedScenesAndFormulasAreOneLineErrors) {
    fs::path deep = path("deep.json"), formula = path("formula.json");
    std::ofstream(deep) << R"({"format": "sdf-workbench-scene", "version": 1, "name": )" << std::string(200000, '[')
                        << std::string(200000, ']') << R"(, "root": {"kind": "sphere"}})";
    ProcessResult r = run("render " + deep.string() + " -o " + path("d.png").string());
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.output.find("nested deeper than"), std::string::npos) << r.output.substr(0, 300);
    EXPECT_LT(r.output.size(), 400u);
    std::ofstream(formula) << R"({"format": "sdf-workbench-scene", "version": 1, "root": {"kind": "sdf", "formula": ")"
                           << std::string(100000, '(') << "length(p) - 1" << std::string(100000, ')') << R"("}})";
    ProcessResult f = run("render " + formula.string() + " -o " + path("f.png").string());
    EXPECT_EQ(f.exitCode, 2);
    EXPECT_NE(f.output.find("root.formula: column"), std::string::npos) << f.output.substr(0, 300);
    EXPECT_NE(f.output.find("nests deeper than"), std::string::npos) << f.output.substr(0, 300);
    EXPECT_EQ(filesInFolder(), 2u);
}

// An intersection of many children: a union of translated spheres compiles
// to one fold loop (gl/fold_run.h) and fits.
TEST_F(Cli, TheGlBackendRefusesAShaderThatWouldCompileForMinutes) {
    fs::path scene = path("wide.json");
    std::string children;
    for (int i = 0; i < 600; ++i) {
        children += std::string(i ? ", " : "") + R"({"kind": "translate", "offset": [)" + std::to_string(i * 0.01) +
                    R"(, 0, 0], "children": [{"kind": "sphere", "radius": 0.1}]})";
    }
    std::ofstream(scene) << R"({"format": "sdf-workbench-scene", "version": 1, "root": {"kind": "intersection", "children": [)"
                         << children << "]}}";
    ProcessResult r = run("render " + scene.string() + " -o " + path("w.png").string() + " --backend gl --size 8x8");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.output.find("the scene makes a shader of"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("render it with the CPU backend"), std::string::npos) << r.output;
    EXPECT_EQ(run("render " + scene.string() + " -o " + path("w.png").string() + " --size 8x8").exitCode, 0);
}

}  // namespace
