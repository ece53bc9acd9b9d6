#include <algorithm>
#include <cmath>

#include "image/image.h"

namespace sdfwb::image {

FrameStats frameStats(const Frame& frame) {
    FrameStats stats;
    size_t n = frame.steps.size();
    for (size_t i = 0; i < n; ++i) {
        stats.meanSteps += frame.steps[i];
        stats.maxSteps = std::max(stats.maxSteps, static_cast<double>(frame.steps[i]));
        stats.hitRatio += frame.coverage[i];
    }
    for (float e : frame.evaluations) {
        stats.meanEvaluations += e;
    }
    if (n > 0) {
        stats.meanSteps /= static_cast<double>(n);
        stats.meanEvaluations /= static_cast<double>(n);
        stats.hitRatio /= static_cast<double>(n);
    }
    for (float v : frame.color.rgb) {
        if (!std::isfinite(v)) {
            ++stats.nonFinite;
        }
    }
    return stats;
}

Image stepHeatImage(const Frame& frame, double maxSteps) {
    Image heat(frame.color.width, frame.color.height);
    for (size_t i = 0; i < frame.steps.size(); ++i) {
        float t = maxSteps > 0 ? static_cast<float>(std::clamp(frame.steps[i] / maxSteps, 0.0, 1.0)) : 0.0f;
        LinearRgb c = heatRamp(t);
        heat.rgb[3 * i + 0] = c.r;
        heat.rgb[3 * i + 1] = c.g;
        heat.rgb[3 * i + 2] = c.b;
    }
    return heat;
}

LinearRgb heatRamp(float t) {
    return {std::clamp(2.0f * t - 0.5f, 0.0f, 1.0f), 1.0f - std::abs(2.0f * t - 1.0f), std::clamp(1.0f - 2.0f * t, 0.0f, 1.0f)};
}

}  // namespace sdfwb::image
