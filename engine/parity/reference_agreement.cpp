#include "parity/reference_agreement.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <vector>

#include "image/encoding.h"

namespace sdfwb::parity {
namespace {

// Depths of neighbouring hit pixels further apart than this fraction are an
// occluding contour (one surface in front of another), as much a silhouette as
// the edge against the background.
constexpr double kContourDepthRatio = 0.05;

bool covered(float coverage) { return coverage > 0.5f; }

// The largest channel difference between pixel i of a and pixel j of b (8-bit encodings).
int pixelDifference(const std::vector<std::uint8_t>& a, size_t i, const std::vector<std::uint8_t>& b, size_t j) {
    int largest = 0;
    for (size_t k = 0; k < 3; ++k) largest = std::max(largest, std::abs(int(a[3 * i + k]) - int(b[3 * j + k])));
    return largest;
}

// Pixels of the reference where a surface's outline runs: partly covered,
// a covered neighbour next to an uncovered one, or a depth jump; with
// `encoded`, also a neighbour of another colour.
std::vector<bool> silhouetteEdges(const image::Frame& reference, const std::vector<std::uint8_t>* encoded) {
    const int w = reference.color.width, h = reference.color.height;
    std::vector<bool> edge(reference.color.pixelCount(), false);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const size_t i = static_cast<size_t>(y) * w + x;
            const float c = reference.coverage[i];
            bool isEdge = c > 0.0f && c < 1.0f;
            for (int dy = -1; dy <= 1 && !isEdge; ++dy) {
                for (int dx = -1; dx <= 1 && !isEdge; ++dx) {
                    const int nx = x + dx, ny = y + dy;
                    if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
                    const size_t j = static_cast<size_t>(ny) * w + nx;
                    if (covered(reference.coverage[j]) != covered(c)) {
                        isEdge = true;
                    } else if (encoded && pixelDifference(*encoded, i, *encoded, j) > 8) {
                        isEdge = true;
                    } else if (covered(c)) {
                        const double a = reference.depth[i], b = reference.depth[j];
                        isEdge = std::abs(a - b) > kContourDepthRatio * std::max(a, b);
                    }
                }
            }
            edge[i] = isEdge;
        }
    }
    return edge;
}

// The edges widened by one pixel: an outline moved by less than a pixel
// changes the pixels next to it.
std::vector<bool> dilate(const std::vector<bool>& edge, int w, int h) {
    std::vector<bool> band(edge.size(), false);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            bool near = false;
            for (int dy = -1; dy <= 1 && !near; ++dy) {
                for (int dx = -1; dx <= 1 && !near; ++dx) {
                    const int nx = x + dx, ny = y + dy;
                    near = nx >= 0 && ny >= 0 && nx < w && ny < h && edge[static_cast<size_t>(ny) * w + nx];
                }
            }
            band[static_cast<size_t>(y) * w + x] = near;
        }
    }
    return band;
}

// Both hit, at depths as far apart as an occluding contour: a film over a
// hole, or a hole onto a farther surface, seen even where the colours happen
// to match.
bool depthDiffers(const image::Frame& frame, const image::Frame& reference, size_t i) {
    if (!covered(frame.coverage[i]) || !covered(reference.coverage[i])) return false;
    const double a = frame.depth[i], b = reference.depth[i];
    return std::abs(a - b) > kContourDepthRatio * std::max(a, b);
}

}  // namespace

ReferenceAgreement compareWithReference(const image::Frame& frame, const image::Frame& reference, bool colourEdges) {
    const int w = reference.color.width, h = reference.color.height;
    if (frame.color.width != w || frame.color.height != h) {
        throw std::invalid_argument("frame and reference differ in size");
    }
    const std::vector<std::uint8_t> a = image::encodeSrgb8(frame.color), b = image::encodeSrgb8(reference.color);
    // Geometry is judged off the geometric outlines only: a colour edge (a
    // grid line, a shadow boundary) moves no surface, and on a patterned
    // floor colour edges cover half the image, holes included.
    const std::vector<bool> outline = dilate(silhouetteEdges(reference, nullptr), w, h);
    const std::vector<bool> band = colourEdges ? dilate(silhouetteEdges(reference, &b), w, h) : outline;
    size_t silhouette = 0, silhouetteMask = 0, interiorError = 0, interiorMask = 0, outlinePixels = 0;
    for (size_t i = 0; i < reference.color.pixelCount(); ++i) {
        const bool maskDiffers = std::abs(frame.coverage[i] - reference.coverage[i]) > 0.5f;
        if (outline[i]) {
            ++outlinePixels;
            silhouetteMask += maskDiffers ? 1 : 0;
        } else {
            interiorMask += maskDiffers || depthDiffers(frame, reference, i) ? 1 : 0;
        }
        if (band[i]) {
            ++silhouette;
        } else {
            interiorError += pixelDifference(a, i, b, i) > 8 ? 1 : 0;
        }
    }
    const double all = static_cast<double>(reference.color.pixelCount());
    ReferenceAgreement r;
    r.silhouettePercent = 100.0 * static_cast<double>(silhouette) / all;
    r.silhouetteMaskPercent = 100.0 * static_cast<double>(silhouetteMask) / all;
    r.interiorErrorPercent = 100.0 * static_cast<double>(interiorError) / std::max(1.0, all - double(silhouette));
    r.interiorMaskPercent = 100.0 * static_cast<double>(interiorMask) / std::max(1.0, all - double(outlinePixels));
    return r;
}

}  // namespace sdfwb::parity
