// compareImages, passes and differenceHeatImage on images whose differences
// are set in display levels, so every figure has a known answer.

#include <cmath>
#include <limits>
#include <stdexcept>

#include <gtest/gtest.h>

#include "image/compare.h"
#include "image/encoding.h"

namespace sdfwb::image {
namespace {

// An image whose every channel encodes to display level `level`.
Image uniform(int width, int height, int level) {
    Image image(width, height);
    for (float& v : image.rgb) v = decodeSrgb8(static_cast<std::uint8_t>(level));
    return image;
}

// Sets channel `channel` of pixel (x, y) to display level `level`.
void setLevel(Image& image, int x, int y, int channel, int level) {
    image.rgb[3 * (static_cast<size_t>(y) * static_cast<size_t>(image.width) + static_cast<size_t>(x)) +
              static_cast<size_t>(channel)] = decodeSrgb8(static_cast<std::uint8_t>(level));
}

TEST(Encoding, EveryLevelDecodesToALinearValueThatEncodesBack) {
    for (int level = 0; level < 256; ++level) {
        EXPECT_EQ(encodeSrgb8(decodeSrgb8(static_cast<std::uint8_t>(level))), level);
    }
    EXPECT_EQ(encodeSrgb8(-1.0f), 0);
    EXPECT_EQ(encodeSrgb8(2.0f), 255);
}

TEST(CompareImages, IdenticalImagesHaveNoDifference) {
    Image a = uniform(7, 5, 100);
    Comparison c = compareImages(a, a);
    EXPECT_EQ(c.width, 7);
    EXPECT_EQ(c.height, 5);
    EXPECT_EQ(c.maxAbs, 0.0);
    EXPECT_EQ(c.meanAbs, 0.0);
    EXPECT_EQ(c.rmse, 0.0);
    EXPECT_EQ(c.psnr, std::numeric_limits<double>::infinity());
    EXPECT_EQ(c.pixelMaxHistogram[0], 35u);
    EXPECT_FALSE(c.linearMaxAbs.has_value());
    EXPECT_TRUE(passes(c, kParityThresholds));
}

TEST(CompareImages, DifferentSizesThrow) {
    EXPECT_THROW(compareImages(Image(4, 4), Image(4, 5)), std::invalid_argument);
    EXPECT_THROW(compareImages(Image(4, 4), Image(5, 4)), std::invalid_argument);
}

TEST(CompareImages, OneChannelOfOnePixelGivesEveryFigure) {
    Image a = uniform(10, 10, 0), b = a;
    setLevel(b, 3, 7, 1, 255);
    Comparison c = compareImages(a, b);
    EXPECT_EQ(c.maxAbs, 255.0);
    EXPECT_EQ(c.worstX, 3);
    EXPECT_EQ(c.worstY, 7);
    EXPECT_DOUBLE_EQ(c.meanAbs, 255.0 / 300.0);
    EXPECT_DOUBLE_EQ(c.rmse, std::sqrt(255.0 * 255.0 / 300.0));
    EXPECT_NEAR(c.psnr, 10.0 * std::log10(300.0), 1e-9);
    EXPECT_DOUBLE_EQ(c.percentAbove1, 1.0);
    EXPECT_DOUBLE_EQ(c.percentAbove8, 1.0);
    EXPECT_EQ(c.pixelMaxHistogram[255], 1u);
    EXPECT_EQ(c.pixelMaxHistogram[0], 99u);
    EXPECT_DOUBLE_EQ(c.percentAbove(254), 1.0);
    EXPECT_DOUBLE_EQ(c.percentAbove(255), 0.0);
}

TEST(CompareImages, TheWorstPixelIsTheFirstWithTheLargestDifference) {
    Image a = uniform(6, 4, 50), b = a;
    setLevel(b, 5, 0, 2, 53);
    setLevel(b, 1, 2, 0, 56);
    setLevel(b, 4, 3, 1, 56);
    Comparison c = compareImages(a, b);
    EXPECT_EQ(c.maxAbs, 6.0);
    EXPECT_EQ(c.worstX, 1);
    EXPECT_EQ(c.worstY, 2);
    EXPECT_DOUBLE_EQ(c.percentAbove(2), 100.0 * 3.0 / 24.0);
    EXPECT_DOUBLE_EQ(c.percentAbove(3), 100.0 * 2.0 / 24.0);
}

TEST(CompareImages, LinearInputsReportTheLargestLinearDifference) {
    Image a(2, 1), b(2, 1);
    b.rgb[4] = 0.25f;
    b.rgb[5] = -0.5f;
    Comparison c = compareImages(a, b, true);
    ASSERT_TRUE(c.linearMaxAbs.has_value());
    EXPECT_DOUBLE_EQ(*c.linearMaxAbs, 0.5);
}

// 1000 pixels: at most 0.1 % (one pixel) may differ by more than one level.
TEST(Passes, EachThresholdDecidesAtItsBoundary) {
    const ParityThresholds& t = kParityThresholds;
    Image a = uniform(40, 25, 128);

    Image onePixel = a;
    setLevel(onePixel, 0, 0, 0, 130);
    EXPECT_TRUE(passes(compareImages(a, onePixel), t));
    Image twoPixels = onePixel;
    setLevel(twoPixels, 1, 0, 0, 130);
    EXPECT_FALSE(passes(compareImages(a, twoPixels), t)) << "0.2 % of pixels above one level";

    Image oneLevelEverywhere = uniform(40, 25, 129);
    EXPECT_DOUBLE_EQ(compareImages(a, oneLevelEverywhere).percentAbove(t.failLevel), 0.0);
    EXPECT_FALSE(passes(compareImages(a, oneLevelEverywhere), t)) << "mean difference of one level";

    Image hard = a;
    setLevel(hard, 0, 0, 0, 128 + 8);
    EXPECT_TRUE(passes(compareImages(a, hard), t));
    setLevel(hard, 0, 0, 0, 128 + 9);
    EXPECT_FALSE(passes(compareImages(a, hard), t)) << "a channel more than 8 levels apart";
}

TEST(Passes, NonFinitePixelsAlwaysFail) {
    Image a = uniform(4, 4, 10), b = a;
    b.rgb[5] = std::numeric_limits<float>::quiet_NaN();
    Comparison c = compareImages(a, b);
    EXPECT_EQ(c.nonFiniteA, 0u);
    EXPECT_EQ(c.nonFiniteB, 1u);
    EXPECT_FALSE(passes(c, kParityThresholds));
    b.rgb[5] = std::numeric_limits<float>::infinity();
    EXPECT_FALSE(passes(compareImages(b, a), kParityThresholds));
}

TEST(DifferenceHeatImage, BlackWhereEqualThenBlueYellowRed) {
    Image a = uniform(4, 1, 100), b = a;
    setLevel(b, 1, 0, 0, 101);  // 1 of 8 levels
    setLevel(b, 2, 0, 1, 104);  // half scale
    setLevel(b, 3, 0, 2, 120);  // beyond full scale
    Image heat = differenceHeatImage(a, b, 8.0);
    ASSERT_EQ(heat.width, 4);
    ASSERT_EQ(heat.height, 1);
    auto pixel = [&](int x) {
        const float* p = &heat.rgb[3 * static_cast<size_t>(x)];
        return std::array<float, 3>{p[0], p[1], p[2]};
    };
    EXPECT_EQ(pixel(0), (std::array<float, 3>{0.0f, 0.0f, 0.0f}));
    EXPECT_EQ(pixel(1), (std::array<float, 3>{0.25f, 0.25f, 0.75f}));
    EXPECT_EQ(pixel(2), (std::array<float, 3>{1.0f, 1.0f, 0.0f}));
    EXPECT_EQ(pixel(3), (std::array<float, 3>{1.0f, 0.0f, 0.0f}));
}

}  // namespace
}  // namespace sdfwb::image
