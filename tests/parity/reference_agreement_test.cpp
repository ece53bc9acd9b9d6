// compareWithReference on frames whose defects are known: a film over a hole
// in a striped floor (the colour edges of the stripes must not hide it), a
// hole, and outlines moved by less than a pixel (counted apart).

#include <stdexcept>

#include <gtest/gtest.h>

#include "parity/reference_agreement.h"

namespace sdfwb::parity {
namespace {

constexpr int kSize = 64;

// A floor at depth 10 seen everywhere, striped in two greys every 2 pixels so
// that with colour edges on, every pixel is near a colour edge.
image::Frame stripedFloor() {
    image::Frame f;
    f.color = image::Image(kSize, kSize);
    f.coverage.assign(f.color.pixelCount(), 1.0f);
    f.depth.assign(f.color.pixelCount(), 10.0f);
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            const float grey = (x / 2) % 2 == 0 ? 0.2f : 0.6f;
            for (int k = 0; k < 3; ++k) f.color.rgb[3 * (static_cast<size_t>(y) * kSize + x) + k] = grey;
        }
    }
    return f;
}

// Pixels in [lo, hi)^2 get depth `depth`, colour unchanged (same stripes).
void setDepth(image::Frame& f, int lo, int hi, float depth) {
    for (int y = lo; y < hi; ++y) {
        for (int x = lo; x < hi; ++x) f.depth[static_cast<size_t>(y) * kSize + x] = depth;
    }
}

TEST(ReferenceAgreement, AFrameEqualToItsReferenceAgreesEverywhere) {
    const image::Frame floor = stripedFloor();
    const ReferenceAgreement a = compareWithReference(floor, floor, true);
    EXPECT_EQ(a.interiorErrorPercent, 0.0);
    EXPECT_EQ(a.interiorMaskPercent, 0.0);
    EXPECT_EQ(a.silhouetteMaskPercent, 0.0);
    EXPECT_EQ(a.silhouettePercent, 100.0);  // every pixel is within a pixel of a stripe's edge
}

// A lid left over a hole: the reference sees the floor through it, the frame
// a surface nearer the eye of the same colour. Coverage is full in both.
TEST(ReferenceAgreement, AFilmOverAHoleIsSeenByItsDepthThroughColourEdges) {
    const image::Frame reference = stripedFloor();
    image::Frame frame = stripedFloor();
    setDepth(frame, 16, 48, 5.0f);
    const ReferenceAgreement a = compareWithReference(frame, reference, true);
    EXPECT_EQ(a.interiorErrorPercent, 0.0);  // the colours agree: only the depth tells
    EXPECT_NEAR(a.interiorMaskPercent, 100.0 * 32 * 32 / (kSize * kSize), 1e-9);
}

TEST(ReferenceAgreement, AHoleIsSeenByItsCoverage) {
    image::Frame reference = stripedFloor();
    image::Frame frame = stripedFloor();
    for (int y = 20; y < 30; ++y) {
        for (int x = 20; x < 30; ++x) frame.coverage[static_cast<size_t>(y) * kSize + x] = 0.0f;
    }
    EXPECT_NEAR(compareWithReference(frame, reference, false).interiorMaskPercent, 100.0 * 100 / (kSize * kSize), 1e-9);
}

// A nearer surface ending at x = 32 in the reference; the frame's ends one
// pixel further: the moved outline counts on the silhouettes only.
TEST(ReferenceAgreement, AnOutlineMovedByAPixelCountsApart) {
    image::Frame reference = stripedFloor();
    image::Frame frame = stripedFloor();
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            const size_t i = static_cast<size_t>(y) * kSize + x;
            if (x < 32) reference.depth[i] = 5.0f;
            if (x < 33) frame.depth[i] = 5.0f;
        }
    }
    const ReferenceAgreement a = compareWithReference(frame, reference, false);
    EXPECT_EQ(a.interiorMaskPercent, 0.0);
    EXPECT_GT(a.silhouettePercent, 0.0);
}

TEST(ReferenceAgreement, FramesOfDifferentSizesAreRefused) {
    image::Frame small = stripedFloor();
    small.color = image::Image(8, 8);
    EXPECT_THROW(compareWithReference(small, stripedFloor(), true), std::invalid_argument);
}

}  // namespace
}  // namespace sdfwb::parity
