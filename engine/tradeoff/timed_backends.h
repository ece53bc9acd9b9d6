#pragma once
// The renderers a sweep times: each renders a compiled scene and says how long
// the render took, shader builds excluded (prepare() does those beforehand).

#include <atomic>
#include <memory>
#include <optional>
#include <string>

#include "image/image.h"
#include "program/program.h"

namespace sdfwb::tradeoff {

struct TimedFrame {
    image::Frame frame;
    double seconds = 0;
};

class TimedBackend {
public:
    virtual ~TimedBackend() = default;
    virtual std::string name() const = 0;
    // Builds what rendering programs of this structure needs (a shader, compiled
    // to machine code), so that no timed render pays for it.
    virtual void prepare(const program::Program& program) = 0;
    // Nothing when cancelled.
    virtual std::optional<TimedFrame> render(const program::Program& program, const std::atomic<bool>* cancel) = 0;
};

// The CPU backend in float precision on every hardware thread.
std::unique_ptr<TimedBackend> makeCpuBackend();
// The GL backend in one headless OSMesa context made now and current on the
// calling thread for the backend's life. Throws glcontext::GlError.
std::unique_ptr<TimedBackend> makeGlBackend();

}  // namespace sdfwb::tradeoff
