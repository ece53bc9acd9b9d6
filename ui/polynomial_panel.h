#pragma once
// The polynomial panel: its own window where parametric equations are
// implicitized in the background (ui/polynomial_job.h) with live progress and
// a Cancel button, and the resulting equation is added to the scene as a
// `polynomial` node through the Editor (one undo step).

#include <optional>
#include <string>
#include <vector>

#include <imgui.h>

#include "ui/editor.h"
#include "ui/long_text.h"
#include "ui/polynomial_job.h"
#include "ui/ui_state.h"

namespace sdfwb::ui {

// What the window edits between frames (not part of the scene).
struct PolynomialPanelState {
    bool open = false;
    // Run sends this with parameterRanges set from `ranges` (when boundsFromRanges).
    PolynomialRequest request;
    bool boundsFromRanges = true;        // else the node's default bounds
    std::vector<ParameterRange> ranges;  // of the equations as last read
    std::optional<std::string> readEquations;  // the text `ranges` and `problem` describe
    std::string problem;                 // why those equations cannot run, "" when they can
    ParameterCheck check;                // reads the equations off the UI thread
    double sheetThickness = 0;           // of the node added: 0 the solid F <= 0, else a sheet
    LongTextBoxState resultText;         // the result's box: the path it is saved to
    PolynomialRequest ran;               // what the last Run sent: the result shown is of it
    PolynomialJob job;
};

// Re-reads the equations when they changed since the last call, in the
// background: once read, the ranges of parameters still present are kept,
// new parameters get their defaults, and `problem` says why the equations
// cannot run (with a column) or is cleared. Never waits (the panel calls it
// every frame); until the current text is read, parametersCurrent() is false.
void checkParameters(PolynomialPanelState& state);
// checkParameters, then waits until the current text is read (scripts, tests).
void readParameters(PolynomialPanelState& state);
// `ranges` and `problem` describe the equations as they are now.
bool parametersCurrent(const PolynomialPanelState& state);
// The last Run was of the equations, trigonometric reading and order as they
// are now (else the result shown is marked outdated).
bool resultIsCurrent(const PolynomialPanelState& state);

// Starts the job on the panel's request, the ranges included (after
// readParameters; requires an empty `problem`).
void runPolynomial(PolynomialPanelState& state);

// Adds the outcome's node (polynomialNode) as the root's last child and
// selects it; reports a refused edit to `ui`. Requires outcome.isSurface().
Problems addPolynomialNode(Editor& editor, UiState& ui, const PolynomialOutcome& outcome, double sheetThickness);

// Draws the window while state.open (never blocks: the job is only polled).
// It first appears in `area` (the viewport's rectangle, clear of the status
// bar), at its lower left.
void drawPolynomialPanel(Editor& editor, UiState& ui, PolynomialPanelState& state, ImVec2 areaMin, ImVec2 areaMax);

}  // namespace sdfwb::ui
