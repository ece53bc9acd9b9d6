#pragma once
// A unit ball resting on a plain ground plane at height 0, the camera aimed
// just below its middle: the scene on which the CPU tests watch what the
// tracer does over an open floor. Each test sets its own view and lights.

#include <glm/vec3.hpp>

#include "scene/scene.h"

namespace sdfwb::test {

inline scene::Scene ballOnTheFloor() {
    scene::Scene s;
    scene::Node translate = scene::Node::make(scene::NodeKind::Translate);
    translate.set("offset", glm::dvec3(0, 1, 0));
    translate.children.push_back(scene::Node::make(scene::NodeKind::Sphere));
    s.root.children.push_back(translate);
    s.environment.ground.enabled = true;
    s.environment.ground.pattern = scene::GroundPattern::Plain;
    s.environment.ground.height = 0.0;
    s.camera.target = glm::dvec3(0, 0.5, 0);
    return s;
}

}  // namespace sdfwb::test
