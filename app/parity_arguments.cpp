#include "app/parity_arguments.h"

#include <string>

#include "scene/scene.h"

namespace sdfwb::app {

CLI::App* addParityCommand(CLI::App& app, ParityArguments& a) {
    CLI::App* parity = app.add_subcommand("parity", "Render scenes with both backends and report how far they differ");
    parity->add_option("scenes", a.paths, "Scene files or folders (default: scenes)");
    parity->add_option("--size", a.size, "Image size WIDTHxHEIGHT")->capture_default_str();
    parity->add_option("--aa", a.aa, "Antialiasing level 1-" + std::to_string(scene::kMaxAa))
        ->check(CLI::Range(1, scene::kMaxAa))
        ->capture_default_str();
    parity->add_option("--report", a.report, "Also write the table as Markdown to this file");
    return parity;
}

}  // namespace sdfwb::app
