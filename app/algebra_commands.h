#pragma once
// `sdf-workbench implicitize` and `sdf-workbench groebner`: the algebra library
// from the command line. Polynomials print in the syntax they are read in.

#include "app/algebra_arguments.h"

namespace sdfwb::app {

// 0 on success, 2 for bad input (one line naming the column), 3 when the
// computation gave up (time or memory limit).
int runImplicitize(const ImplicitizeArguments& arguments);
int runGroebner(const GroebnerArguments& arguments);

}  // namespace sdfwb::app
