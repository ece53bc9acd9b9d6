#pragma once
// Direct selection in the viewport: a click picks the node the pixel shows
// (cpu/pick.h: the shared CPU path, the same math as the GLSL backend), and
// the selection's outline is its world bounds projected into the image.

#include <optional>

#include <glm/vec2.hpp>

#include "cpu/pick.h"
#include "ui/editor.h"

namespace sdfwb::ui {

// The pick of image point (x, y), in pixels from the top left of a
// width x height view of the scene.
cpu::PickResult pickView(const scene::Scene& scene, int width, int height, double x, double y);

// Selects what the pick names; a miss or the ground clears the selection.
void selectPicked(Editor& editor, const cpu::PickResult& pick);

// The image rectangle (top-left, bottom-right pixels) that the node's world
// bounds cover in a width x height view; nullopt when unbounded, missing,
// not drawn (hidden or left out by a solo), or wholly behind the eye.
struct ImageRect {
    glm::dvec2 min, max;
};
std::optional<ImageRect> outlineRect(const scene::Scene& scene, const NodePath& path, int width, int height);

// Where a world point appears in the view (pixels from the top left);
// nullopt behind the eye.
std::optional<glm::dvec2> projectToView(const scene::Scene& scene, const glm::dvec3& world, int width, int height);

// The eye ray through image point (x, y): projectToView's inverse.
struct ViewRay {
    glm::dvec3 origin, direction;  // direction unit
};
ViewRay viewRay(const scene::Scene& scene, int width, int height, const glm::dvec2& point);

}  // namespace sdfwb::ui
