#pragma once
// "Frame all": the orbit camera aimed at a subtree's bounds (program::nodeBounds)
// from the same direction, at a distance where the bounding sphere fits the
// field of view. Unbounded or empty subtrees keep the camera as it is.

#include "scene/scene.h"

namespace sdfwb::app::gui {

scene::Camera framedCamera(const scene::Camera& camera, const scene::Node& node);

}  // namespace sdfwb::app::gui
