#pragma once
// Image comparison on the display encoding (encoding.h), as the compare command
// and the parity suite use it, with thresholds in one place.

#include <array>
#include <cstddef>
#include <optional>

#include "image/image.h"

namespace sdfwb::image {

// Parity thresholds (issue: CPU/GPU parity), in 8-bit display levels.
struct ParityThresholds {
    double failLevel = 1.0;          // a pixel "fails" when any channel differs by more than this
    double failPercent = 0.1;        // at most this percentage of pixels may fail
    double hardFailLevel = 8.0;      // no channel may differ by more than this
    double maxMeanLevel = 0.1;       // mean absolute difference must stay below this
};
inline constexpr ParityThresholds kParityThresholds{};

struct Comparison {
    int width = 0;
    int height = 0;
    double maxAbs = 0;        // levels of 255
    double meanAbs = 0;       // levels of 255, over all channels
    double rmse = 0;          // levels of 255
    double psnr = 0;          // dB; infinity for identical images
    double percentAbove1 = 0; // % of pixels with any channel > 1 level apart
    double percentAbove2 = 0;
    double percentAbove8 = 0;
    int worstX = 0, worstY = 0;
    std::optional<double> linearMaxAbs;  // when both inputs are linear (EXR)
    size_t nonFiniteA = 0, nonFiniteB = 0;
    std::array<size_t, 256> pixelMaxHistogram{};  // pixels by their largest channel difference

    // Percentage of pixels whose largest channel difference exceeds `level`.
    double percentAbove(double level) const;
};

// Throws std::invalid_argument when the sizes differ.
Comparison compareImages(const Image& a, const Image& b, bool linearInputs = false);

// Whether `c` satisfies `t`; non-finite pixels always fail.
bool passes(const Comparison& c, const ParityThresholds& t);

// Heat image of the per-pixel maximum channel difference: black for equal,
// through blue and yellow to red at `fullScaleLevels` levels and beyond.
Image differenceHeatImage(const Image& a, const Image& b, double fullScaleLevels = 8.0);

}  // namespace sdfwb::image
