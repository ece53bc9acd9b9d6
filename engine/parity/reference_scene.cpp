#include "parity/reference_scene.h"

#include <algorithm>

namespace sdfwb::parity {

scene::Scene referenceScene(const scene::Scene& scene, double tightening) {
    scene::Scene tight = scene;
    tight.render.epsilon /= tightening;
    tight.render.maxSteps = std::min(scene::kMaxSteps, static_cast<int>(tight.render.maxSteps * tightening));
    tight.render.shadowSteps = std::min(scene::kMaxShadowSteps, static_cast<int>(tight.render.shadowSteps * tightening));
    return tight;
}

}  // namespace sdfwb::parity
