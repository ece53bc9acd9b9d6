#pragma once
// `sdf-workbench tradeoff`: what each quality setting costs and what it buys,
// measured against a reference (engine/tradeoff), as a Markdown report with plots.

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
// 0 when the report was written, 130 when interrupted (no report), 2 on bad input, 1 on other errors.
int runTradeoff(const TradeoffArguments& arguments);

}  // namespace sdfwb::app
