#pragma once
// `sdf-workbench parity`: renders scenes with both backends and tabulates the difference.

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace sdfwb::app {

struct ParityArguments {
    std::vector<std::string> paths;  // scene files or folders (searched recursively)
    std::string size = "320x180";
    int aa = 2;
    std::string report;              // optional Markdown report file
};

CLI::App* addParityCommand(CLI::App& app, ParityArguments& arguments);
// 0 when every scene passes, 1 when some fail, 2 on an error.
int runParity(const ParityArguments& arguments);

}  // namespace sdfwb::app
