#pragma once
// A rendered frame as both backends produce it: linear float RGB, rows top to
// bottom, plus per-pixel statistics of the march.

#include <cstddef>
#include <vector>

namespace sdfwb::image {

struct Image {
    int width = 0;
    int height = 0;
    std::vector<float> rgb;  // 3 floats per pixel, linear radiance, row-major from the top row

    Image() = default;
    Image(int w, int h) : width(w), height(h), rgb(static_cast<size_t>(w) * static_cast<size_t>(h) * 3, 0.0f) {}
    size_t pixelCount() const { return static_cast<size_t>(width) * static_cast<size_t>(height); }
};

struct Frame {
    Image color;
    std::vector<float> steps;     // mean primary-march evaluations per sub-sample, per pixel
    std::vector<float> evaluations;  // mean field evaluations of any kind (march, normal, material, AO, shadow) per sub-sample
    std::vector<float> coverage;  // fraction of sub-samples that hit a surface, per pixel
    std::vector<float> depth;     // mean march distance t of the sub-samples that hit (0 where none did)
};

struct FrameStats {
    double meanSteps = 0;
    double maxSteps = 0;
    double meanEvaluations = 0;  // all field evaluations per sub-sample, averaged over pixels
    double hitRatio = 0;     // mean coverage
    size_t nonFinite = 0;    // NaN or infinite colour components
};

FrameStats frameStats(const Frame& frame);

// Step-count heat image: steps / maxSteps mapped through heatRamp (linear RGB).
Image stepHeatImage(const Frame& frame, double maxSteps);

// The heat view's ramp at t in [0, 1]: blue (few steps), green, red (many); linear RGB.
// The viewport's legend draws the same ramp.
struct LinearRgb {
    float r, g, b;
};
LinearRgb heatRamp(float t);

}  // namespace sdfwb::image
