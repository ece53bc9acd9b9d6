// Fuzz target: the image reader behind textures and environment maps
// (image/mipmapped_images.h), as a scene's image file reaches it. The first
// byte picks the file's extension (PNG, JPEG, EXR, TIFF: OpenImageIO picks
// its reader by it), the rest is the file. A file either becomes a square
// mipmapped image of finite texels within the side asked for, or is refused
// with std::runtime_error.

#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "image/mipmapped_images.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace sdfwb::image;
    if (size == 0) return 0;
    static const char* const kExtensions[] = {".png", ".jpg", ".exr", ".tif"};
    const std::filesystem::path file = std::filesystem::temp_directory_path() /
                                       ("sdfwb_fuzz_image_" + std::to_string(::getpid()) + kExtensions[data[0] % 4]);
    {
        std::ofstream out(file, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(data + 1), static_cast<std::streamsize>(size - 1));
    }
    constexpr int kMaxSide = 64;  // resampling work stays small per input
    try {
        MipmappedImages images = loadMipmappedImages({file}, kMaxSide);
        const std::size_t side = static_cast<std::size_t>(images.side);
        if (images.side < 1 || images.side > kMaxSide || (images.side & (images.side - 1)) != 0) std::abort();
        if (images.texels.size() != (4 * side * side - 1) / 3) std::abort();
        for (const auto& texel : images.texels) {
            for (int c = 0; c < 4; ++c) {
                if (!std::isfinite(texel[c]) || texel[c] < 0 || texel[c] > kMaxTexelValue) std::abort();
            }
        }
    } catch (const std::runtime_error&) {
    }
    std::filesystem::remove(file);
    return 0;
}
