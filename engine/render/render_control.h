#pragma once
// How a caller steers one render and what it gets back, the same for every
// backend (render/render_backend.h).

#include <atomic>
#include <functional>

#include "image/image.h"
#include "render/tiles.h"

namespace sdfwb::render {

// The CPU backend's arithmetic; the GL backend always renders in float.
enum class Precision { Float, Double };

struct RenderControl {
    int threads = 0;   // CPU worker threads; 0: all hardware threads
    int tileSize = 0;  // pixels per side of a tile; 0: the backend's default
    Precision precision = Precision::Float;
    // Only this rectangle of the frame (rows from the top, clipped to the
    // frame); the rest of the frame stays blank. Unset: the whole frame.
    std::optional<TileRect> region = {};
    // false: a CPU render takes its program's prune grid (prune/prune_grid.h)
    // only when it is built, and evaluates the whole program meanwhile (the
    // same floats, dearer per sample) while the grid builds in the
    // background: for a small preview that is quicker than waiting. The GL
    // backend in a window never waits (it takes the grid up between draws).
    bool waitForPruneGrid = true;
    const std::atomic<bool>* cancel = nullptr;  // checked before each tile (GL: each draw)
    // Called as work completes (tiles on the CPU, draws on GL), one call at a
    // time, from whichever thread did the work.
    std::function<void(int done, int total)> progress = {};
};

struct RenderOutcome {
    image::Frame frame;  // empty when cancelled
    bool cancelled = false;
};

}  // namespace sdfwb::render
