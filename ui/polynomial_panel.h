#pragma once
// The polynomial panel: its own window where parametric equations are
// implicitized in the background (ui/polynomial_job.h) with live progress and
// a Cancel button, and the resulting equation is added to the scene as a
// `polynomial` node through the Editor (one undo step).

#include "ui/editor.h"
#include "ui/polynomial_job.h"
#include "ui/ui_state.h"

namespace sdfwb::ui {

// What the window edits between frames (not part of the scene).
struct PolynomialPanelState {
    bool open = false;
    PolynomialRequest request;
    bool useRange = false;  // bounds from the parameter range, else the node's defaults
    double rangeMin = -1, rangeMax = 1;
    PolynomialJob job;
};

// Adds the outcome's node as the root's last child and selects it; reports a
// refused edit to `ui`. Requires outcome.isSurface().
Problems addPolynomialNode(Editor& editor, UiState& ui, const PolynomialOutcome& outcome);

// Draws the window while state.open (never blocks: the job is only polled).
void drawPolynomialPanel(Editor& editor, UiState& ui, PolynomialPanelState& state);

}  // namespace sdfwb::ui
