#pragma once
// `sdf-workbench implicitize` and `sdf-workbench groebner`: the algebra library
// from the command line. Polynomials print in the syntax they are read in.

#include <string>

#include <CLI/CLI.hpp>

namespace sdfwb::app {

struct ImplicitizeArguments {
    std::string equations;  // "x = u*v; y = v; z = u^2"
    bool json = false;
    std::string trig = "cos-sin";  // or "half-angle" (measured slower: docs/expression-language.md)
    std::string order = "elimination";  // a name of algebra::eliminationOrders()
    double timeout = 300;             // seconds, 0 = none (timeout_argument.h)
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

// 0 on success, 2 for bad input (one line naming the column), 3 when the
// computation gave up (time or memory limit).
int runImplicitize(const ImplicitizeArguments& arguments);
int runGroebner(const GroebnerArguments& arguments);

}  // namespace sdfwb::app
