#pragma once
// Formulas that start with a minus sign on the command line: CLI11 reads
// "-x^2 + y; x*y - 1" as the short option -x, and the formula goes missing.

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace sdfwb::app {

// For the subcommands named in `formulaCommands`: an argument after the
// subcommand that starts with '-', holds a character no option name has
// (space, ^, *, +, ;, (, ...) and names no option of that subcommand is moved
// behind "--", where CLI11 reads it as the positional it is. `arguments` are
// argv[1..] in order; the result is in the same order.
std::vector<std::string> formulasAsPositionals(std::vector<std::string> arguments, const CLI::App& app,
                                               const std::vector<std::string>& formulaCommands);

}  // namespace sdfwb::app
