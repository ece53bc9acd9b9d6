#pragma once
// Per-pixel judgement of a float frame against a double-precision reference
// of a hard case. A hit ratio alone cannot see a hole that a film elsewhere
// balances, nor two backends making the same mistake; the pixels can. Pixels
// on the reference's silhouettes (where a surface meets the background or a
// farther surface) are counted apart: a surface widened by the pixel epsilon
// moves its outline by a fraction of a pixel, and a surface with a long
// outline must not fail for that. Against a reference with a tighter epsilon,
// every sharp edge of the image (grid lines, shadow boundaries, highlights)
// moves a little too: those can be counted apart as well.

#include "image/image.h"

namespace sdfwb::parity {

struct ReferenceAgreement {
    double silhouettePercent = 0;      // % of pixels within one pixel of a silhouette (or edge) of the reference
    double silhouetteMaskPercent = 0;  // % of pixels, on silhouettes, whose coverage differs by more than 1/2
    double interiorErrorPercent = 0;   // % of the other pixels whose colour differs by more than 8/255
    double interiorMaskPercent = 0;    // % of the pixels off the geometric outlines whose coverage differs by
                                       // more than 1/2 or whose depth differs like an occluding contour
};

// `colourEdges`: also count apart, for the colour error only, pixels within
// one pixel of a colour edge of the reference (a neighbour more than 8/255
// away); coverage and depth are judged off the geometric outlines alone. Throws
// std::invalid_argument when the sizes differ.
ReferenceAgreement compareWithReference(const image::Frame& frame, const image::Frame& reference, bool colourEdges);

}  // namespace sdfwb::parity
