#include "app/tradeoff_arguments.h"

namespace sdfwb::app {

CLI::App* addTradeoffCommand(CLI::App& app, TradeoffArguments& a) {
    CLI::App* c = app.add_subcommand("tradeoff",
                                     "Measure what quality settings cost in time and in error against a "
                                     "reference, and write a report with Pareto fronts");
    c->add_option("scenes", a.paths, "Scene files or folders (searched for .json)")->required();
    c->add_option("--backend", a.backend, "Backends to time: cpu, gl or both (interleaved)")
        ->check(CLI::IsMember({"cpu", "gl", "both"}))
        ->capture_default_str();
    c->add_option("--knobs", a.knobs,
                  "Knobs to sweep, each NAME or NAME=V1,V2,... (default: all, with values around the scene's); a "
                  "knob is a render setting of docs/scene-format.md, and an unknown name is answered with the list");
    c->add_option("--budget", a.budget, "Stop sweeping after this many seconds and report what was skipped")
        ->check(CLI::Range(0.0, 1e7));
    c->add_option("--report", a.report, "Markdown report to write")->required();
    auto* plotDir = c->add_option("--plot-dir", a.plotDir, "Write one time-against-error plot (PNG) per scene here");
    c->add_option("--plot", a.plot, "With one scene: write its plot (PNG) to this file")->excludes(plotDir);
    c->add_option("--size", a.size, "Image size WIDTHxHEIGHT")->capture_default_str();
    c->add_option("--repetitions", a.repetitions, "Timed renders per setting and backend (median reported)")
        ->check(CLI::Range(1, 50))
        ->capture_default_str();
    c->add_option("--cache", a.cacheDir,
                  "Folder of cached reference renders (default: $XDG_CACHE_HOME/sdf-workbench/references)");
    return c;
}

}  // namespace sdfwb::app
