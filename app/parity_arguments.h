#pragma once
// `sdf-workbench parity`: its options.
// Light on purpose: the launcher parses every command line with these alone
// (app/command_line.h) before it starts the module that runs the command.

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace sdfwb::app {

struct ParityArguments {
    std::vector<std::string> paths;  // scene files or folders (searched recursively)
    std::string size = "320x180";
    int aa = 2;
    std::string report;  // optional Markdown report file
};

CLI::App* addParityCommand(CLI::App& app, ParityArguments& arguments);

}  // namespace sdfwb::app
