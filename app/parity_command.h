#pragma once
// `sdf-workbench parity`: renders scenes with both backends and tabulates the difference.

#include "app/parity_arguments.h"

namespace sdfwb::app {

// 0 when every scene passes, 1 when some fail, 2 on an error.
int runParity(const ParityArguments& arguments);

}  // namespace sdfwb::app
