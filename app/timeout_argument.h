#pragma once
// --timeout of the algebra commands: a positive finite number of seconds, or
// "none" for no limit (nan, inf, 0 and negative values are refused).

#include <optional>

#include <CLI/CLI.hpp>

namespace sdfwb::app {

// Adds --timeout to `command`; `seconds` becomes 0 for "none".
CLI::Option* addTimeoutOption(CLI::App* command, double& seconds);

// The time limit `seconds` stands for (std::nullopt for "none").
std::optional<double> timeLimit(double seconds);

}  // namespace sdfwb::app
