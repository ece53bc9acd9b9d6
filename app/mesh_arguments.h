#pragma once
// `sdf-workbench mesh`: its options.
// Light on purpose: the launcher parses every command line with these alone
// (app/command_line.h) before it starts the module that runs the command.

#include <string>

#include <CLI/CLI.hpp>

namespace sdfwb::app {

struct MeshArguments {
    std::string scene;  // path, or "" for the embedded default scene
    std::string output;
    int resolution = 0;  // 0: mesh::kDefaultResolution
};

CLI::App* addMeshCommand(CLI::App& app, MeshArguments& arguments);

}  // namespace sdfwb::app
