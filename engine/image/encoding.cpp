#include "image/encoding.h"

#include <algorithm>
#include <cmath>

namespace sdfwb::image {

float srgbFromLinear(float linear) {
    // NaN maps to 0 rather than being undefined in the callers' casts.
    float c = std::isnan(linear) ? 0.0f : std::clamp(linear, 0.0f, 1.0f);
    float srgb = c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
    return std::clamp(srgb, 0.0f, 1.0f);
}

float linearFromSrgb(float s) { return s <= 0.04045f ? s / 12.92f : std::pow((s + 0.055f) / 1.055f, 2.4f); }

std::uint8_t encodeSrgb8(float linear) { return static_cast<std::uint8_t>(std::lround(srgbFromLinear(linear) * 255.0f)); }

std::vector<std::uint8_t> encodeSrgb8(const Image& image) {
    std::vector<std::uint8_t> bytes(image.rgb.size());
    std::transform(image.rgb.begin(), image.rgb.end(), bytes.begin(), [](float v) { return encodeSrgb8(v); });
    return bytes;
}

float decodeSrgb8(std::uint8_t value) { return linearFromSrgb(static_cast<float>(value) / 255.0f); }

}  // namespace sdfwb::image
