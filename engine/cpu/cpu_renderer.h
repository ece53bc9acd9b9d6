#pragma once
// The reference backend: renders a Program on the CPU, in tiles across threads.
// Output is bit-identical for any thread count (each pixel is computed
// independently, in a fixed sub-sample order), matching the GLSL backend's
// float path within parity thresholds; Precision::Double is the reference.

#include <atomic>
#include <functional>

#include "image/image.h"
#include "program/program.h"

namespace sdfwb::cpu {

enum class Precision { Float, Double };

struct RenderControl {
    int threads = 0;                     // 0: all hardware threads
    int tileSize = 32;                   // pixels
    Precision precision = Precision::Float;
    const std::atomic<bool>* cancel = nullptr;  // checked before each tile
    // Called after each tile from worker threads (serialised by the renderer).
    std::function<void(int tilesDone, int tilesTotal)> progress = {};
};

struct RenderOutcome {
    image::Frame frame;
    bool cancelled = false;
};

RenderOutcome renderCpu(const program::Program& program, const RenderControl& control = {});

// The scene's distance at a world point (for tests and tools), at the given precision.
double evaluateDistance(const program::Program& program, const glm::dvec3& marchPoint, Precision precision);

}  // namespace sdfwb::cpu
