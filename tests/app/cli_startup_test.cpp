// The launcher answers --help and bad arguments without loading the engine's
// libraries, and each command loads only those of its module
// (app/command_modules.h). The dynamic loader's own report (LD_DEBUG=files)
// says which shared objects a run opened.

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "cli_process.h"

namespace {

using sdfwb::test::Cli;
using sdfwb::test::ProcessResult;
using sdfwb::test::run;

bool loaded(const ProcessResult& result, const std::string& library) {
    return result.output.find("file=" + library) != std::string::npos;
}

// One of each heavy family: images, GL, the window, exact algebra, meshing.
constexpr const char* kHeavyLibraries[] = {"libOpenImageIO", "libGL", "libOSMesa", "libglfw", "libflint", "libopenvdb"};

TEST_F(Cli, HelpAndBadArgumentsLoadNoEngineLibrary) {
    for (const char* arguments : {"--help", "render --help", "render --aa 99 -o x.png", "no-such-command"}) {
        ProcessResult r = run(arguments, "LD_DEBUG=files");
        for (const char* library : kHeavyLibraries) {
            EXPECT_FALSE(loaded(r, library)) << arguments << " loaded " << library;
        }
    }
}

TEST_F(Cli, AnAlgebraCommandLoadsTheAlgebraAndNoImageOrWindowLibrary) {
    ProcessResult r = run("groebner \"x^2 - y\" --vars x,y", "LD_DEBUG=files");
    EXPECT_TRUE(loaded(r, "libflint")) << r.output;
    for (const char* library : {"libOpenImageIO", "libGL", "libOSMesa", "libglfw", "libopenvdb"}) {
        EXPECT_FALSE(loaded(r, library)) << library;
    }
}

TEST_F(Cli, AModuleStartedByHandRefusesAnotherModulesCommand) {
    std::filesystem::path mesh = std::filesystem::path(SDFWB_EXECUTABLE).parent_path() / "sdf-workbench-mesh";
    ProcessResult r = sdfwb::test::runProgram(mesh.string(), "groebner x --vars x");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("does not run 'groebner'"), std::string::npos) << r.output;
}

}  // namespace
