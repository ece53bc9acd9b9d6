#pragma once
// The reference backend: renders a Program on the CPU, in tiles across threads.
// Output is bit-identical for any thread count (each pixel is computed
// independently, in a fixed sub-sample order), matching the GLSL backend's
// float path within parity thresholds; Precision::Double is the reference.

#include <functional>

#include "image/image.h"
#include "program/program.h"
#include "render/render_control.h"
#include "render/tiles.h"

namespace sdfwb::cpu {

constexpr int kDefaultTileSize = 32;  // pixels per side, when the control says 0

// The whole frame; the outcome's frame is empty when cancelled.
render::RenderOutcome renderCpu(const program::Program& program, const render::RenderControl& control = {});

// Renders into `frame` (program.width x program.height, as render::blankFrame
// makes it), calling `onTile` after each finished tile from the worker
// threads, one call at a time (with control.progress). Returns false when
// cancelled; the tiles reported by then are complete.
bool renderCpuTiles(const program::Program& program, const render::RenderControl& control, image::Frame& frame,
                    const std::function<void(const render::TileRect&)>& onTile);

// The scene's distance at a world point (for tests and tools), at the given precision.
double evaluateDistance(const program::Program& program, const glm::dvec3& marchPoint, render::Precision precision);

}  // namespace sdfwb::cpu
