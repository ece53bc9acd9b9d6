#pragma once
// `sdf-workbench render`: a headless snapshot of a scene.

#include "app/render_arguments.h"

namespace sdfwb::app {

// Returns the process exit code; prints one-line errors to stderr.
int runRender(const RenderArguments& arguments);

}  // namespace sdfwb::app
