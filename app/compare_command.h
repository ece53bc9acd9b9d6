#pragma once
// `sdf-workbench compare A B`: image difference metrics on the display encoding.

#include <string>

#include "app/compare_arguments.h"

#include "image/compare.h"

namespace sdfwb::app {

// 0 when the thresholds hold, 1 when they do not, 2 on an error.
int runCompare(const CompareArguments& arguments);

// The metrics as printed by compare, one "name: value" per line.
std::string describeComparison(const image::Comparison& comparison);

}  // namespace sdfwb::app
