#pragma once
// Running the sdf-workbench executable from tests: through a shell (arguments
// as typed, stdout and stderr together), or as a child process the test can
// signal (for kills in the middle of a write).

#include <sys/types.h>

#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace sdfwb::test {

struct ProcessResult {
    int exitCode;        // the exit status, or 128 + signal when a signal ended it
    std::string output;  // stdout and stderr together
};

// `arguments` after the executable, through /bin/sh; `prefix` runs before it
// in the same shell (e.g. "ulimit -f 16;").
ProcessResult run(const std::string& arguments, const std::string& prefix = "");
// The same for another program (a module executable next to it).
ProcessResult runProgram(const std::string& program, const std::string& arguments, const std::string& prefix = "");

// Starts the executable with `arguments` (no shell), output discarded.
pid_t start(const std::vector<std::string>& arguments);
// Waits for `pid`; the exit status or 128 + signal as run() reports it.
int waitFor(pid_t pid);

// Blocks until a file whose name contains `part` is created in `folder`
// (inotify: no polling, no clock); returns its name.
std::string waitForFileCreated(const std::filesystem::path& folder, const std::string& part);

// A fresh folder per test, removed afterwards.
class Cli : public ::testing::Test {
protected:
    void SetUp() override;
    void TearDown() override;
    std::filesystem::path path(const std::string& name) const { return folder_ / name; }
    std::size_t filesInFolder() const;

    std::filesystem::path folder_;
};

}  // namespace sdfwb::test
