#include "image/compare.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "image/encoding.h"

namespace sdfwb::image {

Comparison compareImages(const Image& a, const Image& b, bool linearInputs) {
    if (a.width != b.width || a.height != b.height) {
        throw std::invalid_argument("images differ in size: " + std::to_string(a.width) + "x" + std::to_string(a.height) +
                                    " and " + std::to_string(b.width) + "x" + std::to_string(b.height));
    }
    Comparison c;
    c.width = a.width;
    c.height = a.height;
    for (float v : a.rgb) c.nonFiniteA += std::isfinite(v) ? 0 : 1;
    for (float v : b.rgb) c.nonFiniteB += std::isfinite(v) ? 0 : 1;
    std::vector<std::uint8_t> ea = encodeSrgb8(a), eb = encodeSrgb8(b);
    double sum = 0, sumSquares = 0;
    double linearMax = 0;
    for (size_t i = 0; i < a.pixelCount(); ++i) {
        int pixelMax = 0;
        for (size_t k = 0; k < 3; ++k) {
            int d = std::abs(int(ea[3 * i + k]) - int(eb[3 * i + k]));
            pixelMax = std::max(pixelMax, d);
            sum += d;
            sumSquares += double(d) * d;
            linearMax = std::max(linearMax, double(std::abs(a.rgb[3 * i + k] - b.rgb[3 * i + k])));
        }
        if (pixelMax > c.maxAbs) {
            c.maxAbs = pixelMax;
            c.worstX = static_cast<int>(i % static_cast<size_t>(a.width));
            c.worstY = static_cast<int>(i / static_cast<size_t>(a.width));
        }
        ++c.pixelMaxHistogram[static_cast<size_t>(pixelMax)];
    }
    double channels = 3.0 * static_cast<double>(a.pixelCount());
    if (a.pixelCount() > 0) {
        c.meanAbs = sum / channels;
        c.rmse = std::sqrt(sumSquares / channels);
        c.percentAbove1 = c.percentAbove(1);
        c.percentAbove2 = c.percentAbove(2);
        c.percentAbove8 = c.percentAbove(8);
    }
    c.psnr = c.rmse > 0 ? 20.0 * std::log10(255.0 / c.rmse) : std::numeric_limits<double>::infinity();
    if (linearInputs) {
        c.linearMaxAbs = linearMax;
    }
    return c;
}

double Comparison::percentAbove(double level) const {
    size_t total = 0, above = 0;
    for (size_t d = 0; d < pixelMaxHistogram.size(); ++d) {
        total += pixelMaxHistogram[d];
        above += static_cast<double>(d) > level ? pixelMaxHistogram[d] : 0;
    }
    return total == 0 ? 0.0 : 100.0 * static_cast<double>(above) / static_cast<double>(total);
}

bool passes(const Comparison& c, const ParityThresholds& t) {
    if (c.nonFiniteA > 0 || c.nonFiniteB > 0) return false;
    if (c.maxAbs > t.hardFailLevel) return false;
    if (c.meanAbs >= t.maxMeanLevel) return false;
    return c.percentAbove(t.failLevel) <= t.failPercent;
}

Image differenceHeatImage(const Image& a, const Image& b, double fullScaleLevels) {
    std::vector<std::uint8_t> ea = encodeSrgb8(a), eb = encodeSrgb8(b);
    Image heat(a.width, a.height);
    for (size_t i = 0; i < a.pixelCount(); ++i) {
        int d = 0;
        for (size_t k = 0; k < 3; ++k) d = std::max(d, std::abs(int(ea[3 * i + k]) - int(eb[3 * i + k])));
        float t = d == 0 ? 0.0f : static_cast<float>(std::min(1.0, d / fullScaleLevels));
        // 0: black; small: blue; mid: yellow; full scale: red
        float r = d == 0 ? 0.0f : std::clamp(2.0f * t, 0.0f, 1.0f);
        float g = d == 0 ? 0.0f : std::clamp(t < 0.5f ? 2.0f * t : 2.0f - 2.0f * t, 0.0f, 1.0f);
        float bl = d == 0 ? 0.0f : std::clamp(1.0f - 2.0f * t, 0.0f, 1.0f);
        heat.rgb[3 * i] = r;
        heat.rgb[3 * i + 1] = g;
        heat.rgb[3 * i + 2] = bl;
    }
    return heat;
}

}  // namespace sdfwb::image
