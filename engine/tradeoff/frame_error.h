#pragma once
// How far a rendered frame is from the reference: on the display encoding, as
// the compare command reports it, and in geometry, from the coverage and depth
// channels both backends write.

#include "image/compare.h"
#include "image/image.h"

namespace sdfwb::tradeoff {

struct FrameError {
    image::Comparison display;  // levels of 255 (compare's figures)
    double hitMismatch = 0;     // mean |coverage - reference coverage|: the share of sub-samples that hit in one only
    double depthError = 0;      // mean |t - t_ref| / t_ref over pixels every sub-sample of both hit (0 if none)
};

// Throws std::invalid_argument when the sizes differ.
FrameError frameError(const image::Frame& frame, const image::Frame& reference);

}  // namespace sdfwb::tradeoff
