#pragma once
// `sdf-workbench render`: its options.
// Light on purpose: the launcher parses every command line with these alone
// (app/command_line.h) before it starts the module that runs the command.

#include <string>

#include <CLI/CLI.hpp>

namespace sdfwb::app {

struct RenderArguments {
    std::string scene;  // path, or "" for the embedded default scene
    std::string output;
    std::string size;  // "WxH", "" = the scene's
    int aa = 0;        // 0 = the scene's
    int threads = 0;   // 0 = all hardware threads
    std::string backend = "cpu";
    std::string precision = "float";
    std::string heat;        // optional step-count heat image
    std::string dumpShader;  // write the generated fragment shader here (gl backend)
    bool stats = false;
    bool noPrune = false;
};

CLI::App* addRenderCommand(CLI::App& app, RenderArguments& arguments);

}  // namespace sdfwb::app
