// The notes' mipmaps (image/mipmaps.h) against their averaging formula, and
// the environment map's images as the shared sampler reads them: square,
// power-of-two, rows from the bottom, unreadable files named in the error.

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include "image/encoding.h"
#include "image/image_io.h"
#include "image/mipmapped_images.h"
#include "image/mipmaps.h"
#include "sdf/shared.h"
#include "support/scratch_folder.h"

namespace sdfwb::image {
namespace {

TEST(Mipmaps, EachLevelIsTheMeanOfFourTexelsOfTheLevelBefore) {
    const int side = 16;
    std::mt19937 random(7);
    std::uniform_real_distribution<float> value(0.0f, 4.0f);
    std::vector<glm::vec4> level0;
    for (int i = 0; i < side * side; ++i) level0.emplace_back(value(random), value(random), value(random), 1.0f);
    std::vector<glm::vec4> texels = buildMipmaps(level0, side);
    ASSERT_EQ(texels.size(), static_cast<size_t>(sdf::f32::mipPyramidTexels(side)));
    for (int level = 1; (side >> level) >= 1; ++level) {
        const int size = side >> level;
        const size_t here = static_cast<size_t>(sdf::f32::mipLevelOffset(side, level));
        const size_t before = static_cast<size_t>(sdf::f32::mipLevelOffset(side, level - 1));
        auto previous = [&](int j, int k) { return texels[before + static_cast<size_t>(k * 2 * size + j)]; };
        for (int k = 0; k < size; ++k) {
            for (int j = 0; j < size; ++j) {
                glm::vec4 expected = (previous(2 * j, 2 * k) + previous(2 * j + 1, 2 * k) + previous(2 * j, 2 * k + 1) +
                                      previous(2 * j + 1, 2 * k + 1)) /
                                     4.0f;
                glm::vec4 got = texels[here + static_cast<size_t>(k * size + j)];
                for (int c = 0; c < 4; ++c) EXPECT_FLOAT_EQ(got[c], expected[c]) << level << " " << j << " " << k;
            }
        }
    }
    // the last level is the mean of the whole image
    glm::vec4 mean(0.0f);
    for (const glm::vec4& t : level0) mean += t;
    mean /= static_cast<float>(side * side);
    EXPECT_NEAR(texels.back().x, mean.x, 1e-5);
}

class MipmappedImagesTest : public testing::Test {
protected:
    sdfwb::test::ScratchFolder folder{"sdfwb_mipmapped_images_"};

    // A width x height image, red on its top row, blue on its bottom row, black between.
    std::filesystem::path redOverBlue(const std::string& name, int width, int height) {
        Image image(width, height);
        for (int x = 0; x < width; ++x) {
            image.rgb[static_cast<size_t>(3 * x)] = 1.0f;
            image.rgb[static_cast<size_t>(3 * ((height - 1) * width + x) + 2)] = 1.0f;
        }
        std::filesystem::path path = folder / name;
        writeImage(path, image);
        return path;
    }
};

TEST_F(MipmappedImagesTest, AnImageBecomesASquareWithRowsFromTheBottom) {
    MipmappedImages images = loadMipmappedImages({redOverBlue("sky.png", 4, 4)}, kMaxEnvironmentSide);
    EXPECT_EQ(images.side, 4);
    EXPECT_EQ(images.levels, 3);
    ASSERT_EQ(images.texels.size(), static_cast<size_t>(sdf::f32::mipPyramidTexels(4)));
    EXPECT_EQ(images.texels[0], glm::vec4(0, 0, 1, 1));   // bottom row first: blue
    EXPECT_EQ(images.texels[12], glm::vec4(1, 0, 0, 1));  // top row: red
}

TEST_F(MipmappedImagesTest, OtherSizesAreResampledToThePowerOfTwoAboveWithinTheLimit) {
    EXPECT_EQ(loadMipmappedImages({redOverBlue("wide.png", 40, 20)}, kMaxEnvironmentSide).side, 64);
    EXPECT_EQ(loadMipmappedImages({redOverBlue("wide.png", 40, 20)}, 16).side, 16);
    // six faces share one side: the largest face's
    std::vector<std::filesystem::path> faces;
    for (int i = 0; i < 6; ++i) faces.push_back(redOverBlue("face" + std::to_string(i) + ".png", i == 3 ? 8 : 4, 4));
    MipmappedImages box = loadMipmappedImages(faces, kMaxBoxFaceSide);
    EXPECT_EQ(box.side, 8);
    EXPECT_EQ(box.texels.size(), static_cast<size_t>(6 * sdf::f32::mipPyramidTexels(8)));
}

TEST_F(MipmappedImagesTest, FilesThatCannotBeReadAreNamedInOneLine) {
    std::filesystem::path text = folder / "notes.png";
    std::ofstream(text) << "not an image";
    for (const std::filesystem::path& path : {folder / "missing.exr", text}) {
        try {
            loadMipmappedImages({path}, kMaxEnvironmentSide);
            ADD_FAILURE() << path;
        } catch (const std::runtime_error& error) {
            std::string message = error.what();
            EXPECT_NE(message.find(path.string()), std::string::npos) << message;
            EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        }
    }
}

// A file is read by the reader of its extension alone: a TIFF named .png is
// refused by the PNG reader instead of being handed to every reader
// OpenImageIO has (camera raw, FITS, DPX...) until one takes it.
TEST_F(MipmappedImagesTest, OnlyTheReaderOfTheFilesExtensionReadsIt) {
    const std::filesystem::path tiff = redOverBlue("sky.tif", 4, 4);
    EXPECT_EQ(readImage(tiff).width, 4);
    const std::filesystem::path disguised = folder / "sky.png";
    std::filesystem::copy_file(tiff, disguised);
    const std::filesystem::path unknown = folder / "sky.xyz";
    std::filesystem::copy_file(tiff, unknown);
    for (const auto& [path, reason] :
         {std::pair{disguised, std::string("PNG")}, std::pair{unknown, std::string("'.xyz'")}}) {
        try {
            readImage(path);
            ADD_FAILURE() << path;
        } catch (const std::runtime_error& error) {
            std::string message = error.what();
            EXPECT_EQ(message.rfind("cannot read image " + path.string() + ": ", 0), 0u) << message;
            EXPECT_NE(message.find(reason), std::string::npos) << message;
            EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        }
    }
}

TEST_F(MipmappedImagesTest, AnImageOverThePixelLimitIsRefusedBeforeItsPixelsAreRead) {
    std::filesystem::path big = redOverBlue("big.png", 64, 64);
    try {
        readImage(big, 1000);
        ADD_FAILURE();
    } catch (const std::runtime_error& error) {
        EXPECT_NE(std::string(error.what()).find("64 x 64 pixels of 3 channels"), std::string::npos) << error.what();
    }
}

TEST_F(MipmappedImagesTest, SixteenBitFilesStoreTheDisplayEncodingAsEightBitOnesDo) {
    // the same grey, 128 of 255, in an 8-bit and a 16-bit PNG
    Image grey(2, 2);
    for (float& value : grey.rgb) value = decodeSrgb8(128);
    const std::filesystem::path eight = folder / "grey8.png", sixteen = folder / "grey16.png";
    writeImage(eight, grey);
    auto out = OIIO::ImageOutput::create(sixteen.string());
    ASSERT_TRUE(out);
    OIIO::ImageSpec spec(2, 2, 1, OIIO::TypeDesc::UINT16);
    ASSERT_TRUE(out->open(sixteen.string(), spec));
    const std::vector<std::uint16_t> stored(4, 128 * 257);
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT16, stored.data()));
    out->close();
    EXPECT_FLOAT_EQ(readImage(eight).rgb[0], decodeSrgb8(128));
    EXPECT_NEAR(readImage(sixteen).rgb[0], decodeSrgb8(128), 1e-6);
    // as data (a bump map's heights) both are the fraction stored
    EXPECT_FLOAT_EQ(readImage(eight, kMaxImageFilePixels, PixelValues::Data).rgb[0], 128.0f / 255.0f);
    EXPECT_NEAR(readImage(sixteen, kMaxImageFilePixels, PixelValues::Data).rgb[0], 128.0f / 255.0f, 1e-6);
    // and an EXR's floats are linear either way
    const std::filesystem::path linear = folder / "grey.exr";
    writeImage(linear, grey);
    EXPECT_FLOAT_EQ(readImage(linear, kMaxImageFilePixels, PixelValues::Data).rgb[0], decodeSrgb8(128));
    // the cache keeps the two readings apart
    EXPECT_NE(cachedMipmappedImages({eight}, 4)->texels[0].x,
              cachedMipmappedImages({eight}, 4, PixelValues::Data)->texels[0].x);
}

// The reader takes images of up to four channels of one type as stored and
// converts them itself, others through OpenImageIO's conversion: every layout
// gives the same colours (as data, so nothing is decoded).
TEST_F(MipmappedImagesTest, EveryChannelLayoutReadsTheSameColours) {
    struct Layout {
        std::string name;
        int channels;
        OIIO::TypeDesc format;
        std::vector<OIIO::TypeDesc> channelFormats;
        float tolerance;
    };
    const std::vector<Layout> layouts = {
        {"rgba8.png", 4, OIIO::TypeDesc::UINT8, {}, 0},
        {"grey_alpha8.png", 2, OIIO::TypeDesc::UINT8, {}, 0},
        {"rgb16.png", 3, OIIO::TypeDesc::UINT16, {}, 1e-6f},
        {"rgba_half.exr", 4, OIIO::TypeDesc::HALF, {}, 1e-3f},
        {"rgb_float.tif", 3, OIIO::TypeDesc::FLOAT, {}, 0},
        {"six_channels.exr", 6, OIIO::TypeDesc::FLOAT, {}, 0},
        {"mixed.exr",
         4,
         OIIO::TypeDesc::FLOAT,
         {OIIO::TypeDesc::HALF, OIIO::TypeDesc::HALF, OIIO::TypeDesc::HALF, OIIO::TypeDesc::FLOAT},
         1e-3f},
    };
    constexpr int kWidth = 3, kHeight = 2;
    for (const Layout& layout : layouts) {
        // multiples of 17 / 255, which 8-bit files hold exactly; an alpha
        // channel opaque, since PNG stores colour unassociated from it
        const size_t channels = static_cast<size_t>(layout.channels);
        std::vector<float> stored(kWidth * kHeight * channels);
        for (size_t i = 0; i < stored.size(); ++i) {
            const bool alpha = (channels == 2 || channels == 4) && i % channels == channels - 1;
            stored[i] = alpha ? 1.0f : static_cast<float>((i * 7 % 16) * 17) / 255.0f;
        }
        const std::filesystem::path path = folder / layout.name;
        auto out = OIIO::ImageOutput::create(path.string());
        ASSERT_TRUE(out) << layout.name;
        OIIO::ImageSpec spec(kWidth, kHeight, layout.channels, layout.format);
        spec.channelformats = layout.channelFormats;
        ASSERT_TRUE(out->open(path.string(), spec)) << layout.name;
        ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, stored.data())) << layout.name;
        ASSERT_TRUE(out->close()) << layout.name;
        // the file holds the layout (channels and their types) the reader is to meet
        auto in = OIIO::ImageInput::open(path.string());
        ASSERT_TRUE(in) << layout.name;
        EXPECT_EQ(in->spec().nchannels, layout.channels) << layout.name;
        EXPECT_EQ(in->spec().channelformats.size(), layout.channelFormats.size()) << layout.name;
        in->close();
        const Image read = readImage(path, kMaxImageFilePixels, PixelValues::Data);
        ASSERT_EQ(read.width, kWidth);
        ASSERT_EQ(read.height, kHeight);
        for (size_t pixel = 0; pixel < read.pixelCount(); ++pixel) {
            for (size_t c = 0; c < 3; ++c) {
                const size_t channel = channels >= 3 ? c : 0;
                EXPECT_NEAR(read.rgb[3 * pixel + c], stored[pixel * channels + channel], layout.tolerance)
                    << layout.name << " pixel " << pixel << " channel " << c;
            }
        }
    }
}

TEST(EnvironmentPlaceholder, IsAMarkedCheckerboardPerImage) {
    auto placeholder = placeholderImages(6);
    EXPECT_EQ(placeholder->texels.size(), static_cast<size_t>(6 * sdf::f32::mipPyramidTexels(placeholder->side)));
    EXPECT_EQ(placeholder->texels[0], glm::vec4(1, 0, 1, 1));
}

}  // namespace
}  // namespace sdfwb::image
