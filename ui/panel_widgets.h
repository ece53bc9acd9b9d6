#pragma once
// Widgets shared by the panels: value editors that commit through the Editor
// with slider drags merged into one undo step.

#include <string>

#include <glm/vec3.hpp>

#include "ui/editor.h"
#include "ui/ui_state.h"

namespace sdfwb::ui {

// What a widget did this frame: changed its value, and/or finished the
// interaction (drag released, typed value entered), which ends the undo merge.
struct WidgetEdit {
    bool changed = false;
    bool finished = false;
    // Text typed into a number field (Ctrl+click or double-click) that is not
    // a finite number ("abc", "nan", "inf"): the value is left as it was and
    // commitEdit reports it.
    std::string notANumber{};
};
// Drag widgets that edit `value` in place.
WidgetEdit dragReal(const char* label, double& value, double speed, double minimum, double maximum,
                    const char* format = "%.3f");
WidgetEdit dragVec3(const char* label, glm::dvec3& value, double speed, double minimum, double maximum,
                    const char* format = "%.3f");
WidgetEdit colorEdit(const char* label, glm::dvec3& value);

// A refused value or formula, wrapped, in the error colour under the widget
// it belongs to (nothing when `problem` is empty).
void problemText(const std::string& problem);

// Commits a scene change made by a widget: merges while the widget stays
// active (key = the widget's id), reports refused edits and text that is not
// a number (under `jsonPath`, the value's path in the scene file, so the
// Problems window can go there), ends the merge when the widget is released.
void commitEdit(Editor& editor, UiState& ui, const WidgetEdit& edit, const char* label,
                const std::function<void(scene::Scene&)>& change, std::string_view jsonPath = {});

}  // namespace sdfwb::ui
