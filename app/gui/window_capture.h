#pragma once
// Saving the window as it was drawn (the back buffer, UI included), for
// `screenshot` in scripts and --screenshot.

#include <filesystem>

#include "glcontext/gl_functions.h"

namespace sdfwb::app::gui {

// Reads the current context's back buffer (width x height pixels, already
// display-encoded) and writes it atomically. Throws std::runtime_error
// naming the path.
void captureWindow(const glcontext::GlFunctions& gl, int width, int height, const std::filesystem::path& path);

}  // namespace sdfwb::app::gui
