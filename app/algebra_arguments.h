#pragma once
// `sdf-workbench implicitize` and `groebner`: their options.
// Light on purpose: the launcher parses every command line with these alone
// (app/command_line.h) before it starts the module that runs the command.

#include <string>

#include <CLI/CLI.hpp>

namespace sdfwb::app {

struct ImplicitizeArguments {
    std::string equations;  // "x = u*v; y = v; z = u^2"
    bool json = false;
    std::string trig = "cos-sin";       // or "half-angle" (measured slower: docs/expression-language.md)
    std::string order = "elimination";  // a name of algebra::eliminationOrders()
    double timeout = 300;               // seconds, 0 = none (timeout_argument.h)
};

struct GroebnerArguments {
    std::string polynomials;  // "f1; f2; ..."
    std::string vars;         // "x0,x1,x2"
    std::string order = "degrevlex";
    bool json = false;
    double timeout = 300;  // seconds, 0 = none
};

CLI::App* addImplicitizeCommand(CLI::App& app, ImplicitizeArguments& arguments);

CLI::App* addGroebnerCommand(CLI::App& app, GroebnerArguments& arguments);

}  // namespace sdfwb::app
