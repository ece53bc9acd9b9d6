#pragma once
// Refusing an image size before allocating it: a render of 16384 x 16384
// pixels needs gigabytes, and running out halfway is a bare std::bad_alloc.

#include <cstddef>

namespace sdfwb::app {

// What a command-line render holds per pixel at its peak: the frame (colour
// and three statistics, 6 floats), the heat image and the read-back check of a
// written file (3 floats each), the 8-bit encoding, and the GL backend's
// targets and read-back buffers (RGBA floats, several).
inline constexpr std::size_t kRenderBytesPerPixel = 128;

// Memory this process may still use: the kernel's MemAvailable, or less when
// an address-space limit (ulimit -v) is set.
std::size_t availableMemoryBytes();

// Throws std::invalid_argument "the image is WxH pixels: rendering it needs
// about N GB, M GB are available" when it does not fit.
void checkRenderFitsInMemory(int width, int height);

}  // namespace sdfwb::app
