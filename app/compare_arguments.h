#pragma once
// `sdf-workbench compare`: its options.
// Light on purpose: the launcher parses every command line with these alone
// (app/command_line.h) before it starts the module that runs the command.

#include <string>

#include <CLI/CLI.hpp>

#include "image/compare.h"

namespace sdfwb::app {

struct CompareArguments {
    std::string first;
    std::string second;
    std::string diff;
    image::ParityThresholds thresholds = image::kParityThresholds;
};

CLI::App* addCompareCommand(CLI::App& app, CompareArguments& arguments);

}  // namespace sdfwb::app
