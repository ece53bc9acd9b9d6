#pragma once
// The one display encoding: linear radiance clamped to [0, 1], sRGB transfer
// function, rounded to 8 bits. Image files, the viewport and every parity
// figure go through it, so what a user sees is what a snapshot writes.

#include <cstdint>
#include <vector>

#include "image/image.h"

namespace sdfwb::image {

// The transfer function on [0, 1] (linear clamped first, NaN as 0) and its inverse;
// colour swatches in the editor show linear values through it, as the render does.
float srgbFromLinear(float linear);
float linearFromSrgb(float srgb);

std::uint8_t encodeSrgb8(float linear);

// 3 bytes per pixel, same layout as image.rgb.
std::vector<std::uint8_t> encodeSrgb8(const Image& image);

// Inverse of the transfer function (for reading 8-bit images back as linear).
float decodeSrgb8(std::uint8_t value);

}  // namespace sdfwb::image
