#include "tradeoff/frame_error.h"

#include <cmath>

namespace sdfwb::tradeoff {

FrameError frameError(const image::Frame& frame, const image::Frame& reference) {
    FrameError e;
    e.display = image::compareImages(frame.color, reference.color);
    size_t pixels = frame.color.pixelCount();
    if (pixels == 0 || frame.coverage.size() != pixels || reference.coverage.size() != pixels) return e;
    double mismatch = 0, depth = 0;
    size_t bothHit = 0;
    for (size_t i = 0; i < pixels; ++i) {
        mismatch += std::abs(double(frame.coverage[i]) - double(reference.coverage[i]));
        // partly covered pixels average the depths of different surfaces
        if (frame.coverage[i] == 1.0f && reference.coverage[i] == 1.0f && reference.depth[i] > 0.0f) {
            depth += std::abs(double(frame.depth[i]) - double(reference.depth[i])) / double(reference.depth[i]);
            ++bothHit;
        }
    }
    e.hitMismatch = mismatch / static_cast<double>(pixels);
    e.depthError = bothHit > 0 ? depth / static_cast<double>(bothHit) : 0.0;
    return e;
}

}  // namespace sdfwb::tradeoff
