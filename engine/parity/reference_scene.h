#pragma once
// The settings of a double-precision reference render: the scene's own with a
// tighter epsilon and more steps, so that the reference converges where the
// scene's settings stop early. The parity suite's hard cases and the
// speed-against-error sweep (engine/tradeoff) measure against it.

#include "scene/scene.h"

namespace sdfwb::parity {

// Hit epsilon divided by `tightening`, primary and shadow step limits
// multiplied by it (up to the largest valid values).
scene::Scene referenceScene(const scene::Scene& scene, double tightening);

}  // namespace sdfwb::parity
