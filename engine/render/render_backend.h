#pragma once
// The contract both backends implement (cpu/cpu_backend.h, the reference
// that always works; gl/gl_backend.h, the GLSL sphere tracer). Callers (the
// render command, parity, the snapshot export, the GUI viewport) hold a
// Backend and never branch on which one it is.

#include <memory>
#include <string>
#include <vector>

#include "program/program.h"
#include "render/render_control.h"
#include "render/tiles.h"

namespace sdfwb::render {

// A render spread over many short calls, for a caller that must never block
// (the viewport): each advance() does or collects a bounded amount of work.
// Destroying it cancels what is left, without waiting.
class ProgressiveRender {
public:
    virtual ~ProgressiveRender() = default;

    // Works for about `budgetSeconds` at most (GL: draws on the calling
    // thread, at least one; CPU: the tiles render on workers and this only
    // collects them) and returns the tiles finished since the last call,
    // already in frame().
    virtual std::vector<TileRect> advance(double budgetSeconds) = 0;
    virtual bool done() const = 0;
    // Fraction of the work done, 0 to 1.
    virtual double progress() const = 0;
    // The frame so far: finished tiles hold their pixels, the rest zeros.
    virtual const image::Frame& frame() const = 0;
    virtual const program::Program& program() const = 0;
    // Wall seconds the render took so far.
    virtual double seconds() const = 0;
    // Device seconds of the work so far, when the backend measures them.
    virtual double deviceSeconds() const { return 0; }
};

// Whether a backend can start rendering a program now.
struct Readiness {
    bool ready = true;
    std::string error;  // why it never will (a shader build report), or ""
};

class Backend {
public:
    virtual ~Backend() = default;

    // "cpu" or "gl", as the command line and image metadata spell it.
    virtual std::string name() const = 0;
    // The device that renders ("CPU", or the GL_RENDERER string).
    virtual std::string device() const = 0;

    // Builds what rendering `program` needs, on the calling thread (GL: its
    // shader). Throws an error with a one-line cause (or a build report).
    virtual void prepare(const program::Program&) {}
    // Seconds the last build in prepare() (or in the background) took; 0
    // when nothing needed building.
    virtual double lastPrepareSeconds() const { return 0; }
    // How many builds prepare() and the background made so far.
    virtual int builds() const { return 0; }
    // For callers that must not wait on a build (the viewport): whether a
    // render can start now without one; when not, a background build is
    // started (once per structure) and a later call reports ready.
    virtual Readiness readiness(const program::Program&) { return {}; }
    // No background build is queued or running.
    virtual bool buildsIdle() const { return true; }

    // The frame (or control.region of it), in tiles, with progress and cancel.
    virtual RenderOutcome render(const program::Program& program, const RenderControl& control = {}) = 0;
    // A render the caller drives with advance(); of `control`, the tile size,
    // region, threads and precision apply (the render has its own cancel and progress).
    virtual std::unique_ptr<ProgressiveRender> startProgressive(program::Program program,
                                                                const RenderControl& control = {}) = 0;
};

}  // namespace sdfwb::render
