#include "app/compare_arguments.h"

namespace sdfwb::app {

CLI::App* addCompareCommand(CLI::App& app, CompareArguments& a) {
    CLI::App* compare = app.add_subcommand("compare", "Compare two images on the 8-bit sRGB display encoding");
    compare->add_option("first", a.first, "First image")->required()->check(CLI::ExistingFile);
    compare->add_option("second", a.second, "Second image")->required()->check(CLI::ExistingFile);
    compare->add_option("--diff", a.diff, "Write a heat image of the per-pixel difference");
    compare->add_option("--fail", a.thresholds.failLevel, "A pixel fails above this many levels of 255")
        ->check(CLI::Range(0, 255))
        ->capture_default_str();
    compare->add_option("--fail-percent", a.thresholds.failPercent, "Allowed percentage of failing pixels")
        ->check(CLI::Range(0, 100))
        ->capture_default_str();
    compare->add_option("--hard-fail", a.thresholds.hardFailLevel, "No channel may differ by more levels than this")
        ->check(CLI::Range(0, 255))
        ->capture_default_str();
    return compare;
}

}  // namespace sdfwb::app
