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
//
// Free spots are searched, not walked to: the spot under the view centre,
// then rings of spots around it on its level (each set down on what is under
// it when the view centre meets a surface), nearest first, each tested by
// FreeSpace (ui/free_space.h) against the bounds of what the scene draws. The
// work is a fixed budget of tests whatever the scene; when no spot in it is
// free, the node goes above everything there is, or as a last resort where
// the view centre is.

#include <optional>

#include <glm/vec3.hpp>

#include "ui/editor.h"

namespace sdfwb::ui {

// ---- the search's budget ----
inline constexpr int kPlacementRings = 8;           // around the first spot
inline constexpr int kPlacementDirections = 12;     // spots on each ring
inline constexpr int kPlacementSettlingSteps = 10;  // bisections back towards the first spot
// every clearance test one search may run: two per spot (set down, level)
// for the first spot, the rings and the settling, and the fallback above
// everything
inline constexpr int kPlacementBudget = 2 * (1 + kPlacementRings * kPlacementDirections + kPlacementSettlingSteps) + 1;

struct PlacementSearch {
    glm::dvec3 point{0.0};  // world position of the box's centre
    bool clear = false;     // false: no free spot within the budget, `point` is the last resort
    int tests = 0;          // clearance tests run, at most kPlacementBudget
};

// Where the centre of a new object goes, given the half extents of its
// world-aligned bounding box: clear of what the scene draws, in front of the
// eye and within the view, near the surface under the view centre.
PlacementSearch searchPlacement(const scene::Scene& scene, const glm::dvec3& halfExtents);
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
