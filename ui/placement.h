#pragma once
// Where new and duplicated nodes appear: where the user is looking, resting
// on the surface under the view centre (or in front of the camera when the
// centre ray meets nothing), clear of other objects; a duplicate beside its
// original. The node is wrapped in a translate (or its own translate moved) so
// that its bounds land there; one undo step, as Editor::insert.
//
// The view centre's ray comes from the shared CPU pick (cpu/pick.h), so the
// surface is the one both backends draw. Unbounded nodes (a plane, an sdf
// formula) and empty booleans go where Editor::add puts them, unmoved.

#include <optional>

#include <glm/vec3.hpp>

#include "ui/editor.h"

namespace sdfwb::ui {

// The world point where the centre of a new object goes, given the half
// extents of its world-aligned bounding box.
glm::dvec3 placementPoint(const scene::Scene& scene, const glm::dvec3& halfExtents);

// Inserts `node` as child `index` of `parent`, placed; selects the node itself
// (inside its translate).
Problems insertPlaced(Editor& editor, const NodePath& parent, int index, scene::Node node);

// Editor::add with the node placed; a kind that needs a child wraps the
// selection as Editor::add does.
Problems addPlaced(Editor& editor, scene::Node node);
Problems addPlaced(Editor& editor, scene::NodeKind kind);

// Editor::duplicate with the copy moved beside the original (to the right in
// the view, else left, above, behind), not overlapping it or another object.
Problems duplicatePlaced(Editor& editor, const NodePath& path);

}  // namespace sdfwb::ui
