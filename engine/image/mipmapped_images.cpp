#include "image/mipmapped_images.h"

#include <algorithm>
#include <cmath>
#include <list>
#include <mutex>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include "image/image_io.h"
#include "image/mipmaps.h"
#include "sdf/shared.h"

namespace sdfwb::image {
namespace {

int powerOfTwoAtLeast(int size, int maxSide) {
    int side = 1;
    while (side < size && side < maxSide) side *= 2;
    return side;
}

float cleanRadiance(float value) { return std::isnan(value) ? 0.0f : std::clamp(value, 0.0f, kMaxTexelValue); }

// The image resampled to side x side (OpenImageIO's triangle filter: no
// negative lobes, so no dark rings around a bright sun), rows from the bottom.
std::vector<glm::vec4> squareTexels(Image image, int side, const std::filesystem::path& file) {
    for (float& value : image.rgb) value = cleanRadiance(value);
    OIIO::ImageBuf source(OIIO::ImageSpec(image.width, image.height, 3, OIIO::TypeDesc::FLOAT), image.rgb.data());
    OIIO::ImageBuf square;
    if (image.width == side && image.height == side) {
        square = source;
    } else if (!OIIO::ImageBufAlgo::resize(square, source, "triangle", 0.0f, OIIO::ROI(0, side, 0, side, 0, 1, 0, 3))) {
        throw std::runtime_error("cannot read image " + file.string() + ": resampling failed: " + square.geterror());
    }
    std::vector<float> rgb(static_cast<std::size_t>(side) * static_cast<std::size_t>(side) * 3);
    square.get_pixels(OIIO::ROI(0, side, 0, side, 0, 1, 0, 3), OIIO::TypeDesc::FLOAT, rgb.data());
    std::vector<glm::vec4> texels;
    texels.reserve(static_cast<std::size_t>(side) * static_cast<std::size_t>(side));
    for (int row = side - 1; row >= 0; --row) {
        for (int column = 0; column < side; ++column) {
            const float* p = &rgb[(static_cast<std::size_t>(row) * static_cast<std::size_t>(side) +
                                   static_cast<std::size_t>(column)) *
                                  3];
            texels.emplace_back(cleanRadiance(p[0]), cleanRadiance(p[1]), cleanRadiance(p[2]), 1.0f);
        }
    }
    return texels;
}

struct CacheKey {
    std::vector<std::filesystem::path> files;
    std::vector<std::uintmax_t> sizes;
    std::vector<std::filesystem::file_time_type> times;
    int maxSide;
    PixelValues values;
    bool operator==(const CacheKey&) const = default;
};

CacheKey keyOf(const std::vector<std::filesystem::path>& files, int maxSide, PixelValues values) {
    CacheKey key{{}, {}, {}, maxSide, values};
    for (const std::filesystem::path& file : files) {
        std::error_code error;
        key.files.push_back(std::filesystem::absolute(file, error));
        key.sizes.push_back(std::filesystem::file_size(file, error));
        key.times.push_back(std::filesystem::last_write_time(file, error));
    }
    return key;
}

}  // namespace

MipmappedImages loadMipmappedImages(const std::vector<std::filesystem::path>& files, int maxSide, PixelValues values) {
    std::vector<Image> images;
    int largest = 1;
    for (const std::filesystem::path& file : files) {
        images.push_back(readImage(file, kMaxImageFilePixels, values));
        largest = std::max({largest, images.back().width, images.back().height});
    }
    MipmappedImages out;
    out.side = powerOfTwoAtLeast(largest, maxSide);
    out.levels = static_cast<int>(std::lround(std::log2(out.side))) + 1;
    for (std::size_t i = 0; i < images.size(); ++i) {
        std::vector<glm::vec4> mipmaps = buildMipmaps(squareTexels(std::move(images[i]), out.side, files[i]), out.side);
        out.texels.insert(out.texels.end(), mipmaps.begin(), mipmaps.end());
    }
    return out;
}

std::shared_ptr<const MipmappedImages> cachedMipmappedImages(const std::vector<std::filesystem::path>& files,
                                                             int maxSide, PixelValues values) {
    // Entries up to a texel budget (the most recent always stays): an editor
    // switching between two maps keeps both, and a scene's textures stay
    // with its map. A failure is kept too (as its message), so a renderer
    // asking every frame does not read a bad file again until it changes
    // (its size or time).
    constexpr std::size_t kEntries = 32;
    constexpr std::size_t kTexelBudget = std::size_t(1) << 24;  // 256 MB
    struct Entry {
        CacheKey key;
        std::shared_ptr<const MipmappedImages> images;
        std::string error;
    };
    static std::mutex mutex;
    static std::list<Entry> entries;
    CacheKey key = keyOf(files, maxSide, values);
    auto answer = [](const Entry& entry) {
        if (!entry.images) throw std::runtime_error(entry.error);
        return entry.images;
    };
    {
        std::lock_guard lock(mutex);
        for (auto it = entries.begin(); it != entries.end(); ++it) {
            if (it->key == key) {
                entries.splice(entries.begin(), entries, it);
                return answer(entries.front());
            }
        }
    }
    Entry entry{std::move(key), nullptr, ""};
    try {
        entry.images = std::make_shared<const MipmappedImages>(loadMipmappedImages(files, maxSide, values));
    } catch (const std::exception& error) {
        entry.error = error.what();
    }
    std::lock_guard lock(mutex);
    entries.push_front(entry);
    auto texels = [&] {
        std::size_t total = 0;
        for (const Entry& e : entries) total += e.images ? e.images->texels.size() : 0;
        return total;
    };
    while (entries.size() > 1 && (entries.size() > kEntries || texels() > kTexelBudget)) entries.pop_back();
    return answer(entry);
}

Image mipmapPreview(const MipmappedImages& images, int index, int maxSide) {
    namespace shared = sdf::f64;
    int level = 0;
    while ((images.side >> level) > std::max(maxSide, 1)) ++level;
    const int side = images.side >> level;
    const std::size_t start =
        static_cast<std::size_t>(shared::mipPyramidTexels(images.side)) * static_cast<std::size_t>(index) +
        static_cast<std::size_t>(shared::mipLevelOffset(images.side, level));
    Image preview(side, side);
    for (int row = 0; row < side; ++row) {
        for (int column = 0; column < side; ++column) {
            // texel rows run from the bottom, image rows from the top
            const glm::vec4& texel = images.texels[start + static_cast<std::size_t>((side - 1 - row) * side + column)];
            for (int c = 0; c < 3; ++c)
                preview.rgb[3 * static_cast<std::size_t>(row * side + column) + static_cast<std::size_t>(c)] = texel[c];
        }
    }
    return preview;
}

std::shared_ptr<const MipmappedImages> placeholderImages(int count) {
    constexpr int kSide = 8;
    std::vector<glm::vec4> level0;
    for (int row = 0; row < kSide; ++row) {
        for (int column = 0; column < kSide; ++column) {
            level0.push_back((row + column) % 2 == 0 ? glm::vec4(1, 0, 1, 1) : glm::vec4(0, 0, 0, 1));
        }
    }
    auto out = std::make_shared<MipmappedImages>();
    out->side = kSide;
    out->levels = 4;
    std::vector<glm::vec4> mipmaps = buildMipmaps(level0, kSide);
    for (int i = 0; i < count; ++i) out->texels.insert(out->texels.end(), mipmaps.begin(), mipmaps.end());
    return out;
}

}  // namespace sdfwb::image
