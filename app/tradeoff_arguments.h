#pragma once
// `sdf-workbench tradeoff`: its options.
// Light on purpose: the launcher parses every command line with these alone
// (app/command_line.h) before it starts the module that runs the command.

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace sdfwb::app {

struct TradeoffArguments {
    std::vector<std::string> paths;  // scene files or folders (searched recursively)
    std::string backend = "both";
    std::vector<std::string> knobs;  // "name" or "name=v1,v2,..."; empty: every knob
    double budget = 0;               // seconds; 0: none
    std::string report;
    std::string plotDir;
    std::string plot;
    std::string size = "320x180";
    int repetitions = 3;
    std::string cacheDir;  // "": $XDG_CACHE_HOME/sdf-workbench/references
};

CLI::App* addTradeoffCommand(CLI::App& app, TradeoffArguments& arguments);

}  // namespace sdfwb::app
