#pragma once
// The view: how mouse drags, keys and menu items move the orbit camera.
// View changes are not edits (Editor::setView: no undo step, the document
// stays unmodified, still saved with the scene), as in Blender. These are
// pure functions of the scene, so tests hold them without a window.

#include <optional>
#include <string_view>

#include "program/bounds.h"
#include "scene/scene.h"
#include "ui/node_path.h"

namespace sdfwb::ui {

// The angles Frame all returns to: the default camera's (30 degrees round,
// 20 degrees above the horizon).
inline constexpr double kHomeAzimuth = 30.0;    // degrees
inline constexpr double kHomeElevation = 20.0;  // degrees

// `camera` aimed at the bounds of `node` (in the node's own frame) from the
// same direction, at a distance where the bounding sphere fits the field of
// view. Unbounded or empty subtrees keep the camera as it is.
scene::Camera framedCamera(const scene::Camera& camera, const scene::Node& node);

// Bounds of the node at `path` in world coordinates: the node's bounds taken
// through every ancestor's transform (the siblings left out).
program::Bounds worldBounds(const scene::Node& root, const NodePath& path);

// Home / Frame all: the whole scene framed from the home angles. When the
// scene is unbounded (a plane, an sdf formula), the target and distance stay.
scene::Camera frameAllCamera(const scene::Scene& scene);
// Frame selected: the camera aimed at the node's world bounds, angles kept;
// nullopt when the node is unbounded or missing.
std::optional<scene::Camera> frameSelectedCamera(const scene::Scene& scene, const NodePath& path);

// The lowest elevation (degrees) that keeps the eye above the ground plane
// (with a margin) when the ground is on; -89 otherwise.
double lowestElevation(const scene::Camera& camera, const scene::Environment& environment);
// Whether the eye is at or below an enabled ground plane (the view is then a
// flat colour: the viewport shows a hint).
bool eyeBelowGround(const scene::Camera& camera, const scene::Environment& environment);

// Orbit by angle steps (degrees); elevation clamped to [lowestElevation, 89].
scene::Camera orbited(const scene::Camera& camera, const scene::Environment& environment, double azimuthStep,
                      double elevationStep);
// Pan the target by a drag of (dx, dy) pixels in a view `viewHeight` pixels high.
scene::Camera panned(const scene::Camera& camera, double dx, double dy, double viewHeight);
// Zoom by wheel notches (positive: closer), the eye kept above the ground.
scene::Camera zoomed(const scene::Camera& camera, const scene::Environment& environment, double notches);

// Axis-aligned views (numeric keypad as in Blender: 1 front, 3 right, 7 top;
// with Ctrl the opposite side). Front looks along -z, right along -x, top down -y.
enum class ViewPreset { Front, Back, Right, Left, Top, Bottom };
scene::Camera presetCamera(const scene::Camera& camera, ViewPreset preset);
// "front", "back", "right", "left", "top", "bottom"; nullopt for any other word.
std::optional<ViewPreset> viewPresetNamed(std::string_view name);

}  // namespace sdfwb::ui
