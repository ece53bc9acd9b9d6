#pragma once
// Move, rotate and scale handles in the viewport (issue 13, item 6): the
// selection's handles are drawn over the image, a press on one starts a drag
// that edits the node's transform, and the whole drag is one undo step.
//
// A drag edits a translate, rotate or scale around the node: the node itself
// when it is one, else one in the chain of transform wrappers directly above
// it, else a new one. A new translate goes outside the chain (its offset in
// the parent's frame); a new rotate or scale goes right around the node, so
// it turns and grows about the point where the node sits. The handles are
// drawn at that point. Scale is uniform (the scene format's scale has one
// factor), so all three scale handles do the same.
//
// Pure functions of the scene, the view size and image points (pixels from
// the top left, as view_picking.h), so tests and scripts drive them without
// a window; the viewport panel only draws and forwards the mouse.

#include <array>
#include <optional>
#include <string_view>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "ui/editor.h"
#include "ui/ui_state.h"

namespace sdfwb::ui {

std::optional<HandleMode> handleModeNamed(std::string_view name);

// Snapping (Ctrl held while dragging): the drag's change is rounded to these.
inline constexpr double kMoveSnap = 0.1;     // scene units
inline constexpr double kRotateSnap = 15.0;  // degrees
inline constexpr double kScaleSnap = 0.1;    // of the factor at the start of the drag

// How close (pixels) a press must come to a handle to take it.
inline constexpr double kHandleReach = 8.0;

// The handles of one node in a width x height view: for move and scale an
// arrow per world axis from the pivot to its tip, for rotate a ring per axis
// (the circle about that axis, projected; points in order round the circle).
struct HandleLayout {
    static constexpr int kRingPoints = 48;
    glm::dvec3 pivotWorld{0.0};
    glm::dvec2 pivot{0.0};
    std::array<glm::dvec2, 3> tip{};                               // move, scale
    std::array<std::array<glm::dvec2, kRingPoints>, 3> ring{};     // rotate
    std::array<bool, 3> visible{true, true, true};  // false: the axis points at the eye (no direction to drag)
};

// nullopt when `path` leads nowhere, its node does not draw, or its pivot is
// behind the eye.
std::optional<HandleLayout> handleLayout(const scene::Scene& scene, const NodePath& path, HandleMode mode, int width,
                                         int height);

// The axis (0 x, 1 y, 2 z) whose handle is within kHandleReach of `point`, the nearest.
std::optional<int> handleAt(const HandleLayout& layout, HandleMode mode, const glm::dvec2& point);

// Where a hand takes the handle of `axis` and the screen direction (unit)
// that increases its value (moves along +axis, turns positively about it,
// grows): what scripts and tests drag. nullopt for a hidden handle.
struct HandleGrip {
    glm::dvec2 point, direction;
};
std::optional<HandleGrip> handleGrip(const HandleLayout& layout, HandleMode mode, int axis);

// One drag of a handle, from press to release.
class HandleDrag {
public:
    // Starts a drag when `point` is on a handle of the selection; false (and
    // nothing starts) otherwise, so the press can orbit instead.
    bool begin(const Editor& editor, HandleMode mode, int width, int height, const glm::dvec2& point);
    // The mouse is at `point`: sets the transform for the drag so far (from
    // the state at the press, so steps do not accumulate error), merged into
    // the drag's one undo step. `snap` rounds the change (kMoveSnap, ...).
    Problems update(Editor& editor, const glm::dvec2& point, bool snap);
    // Release: closes the undo step. A drag that changed nothing left none.
    void end(Editor& editor);

    bool active() const { return active_; }
    int axis() const { return axis_; }

private:
    scene::Scene start_;
    NodePath target_;
    HandleMode mode_ = HandleMode::Move;
    HandleLayout layout_;
    int axis_ = 0;
    int width_ = 0, height_ = 0;
    glm::dvec2 press_{0.0};
    bool active_ = false;
};

}  // namespace sdfwb::ui
