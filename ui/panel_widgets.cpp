#include "ui/panel_widgets.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include <imgui.h>
#include <imgui_internal.h>  // GetItemID: the merge key of a drag; the typed text of a drag field
#include <imgui_stdlib.h>

#include "image/encoding.h"
#include "io/quoted_text.h"
#include "ui/long_text.h"
#include "ui/panels.h"

namespace sdfwb::ui {

namespace {
WidgetEdit finishEdit(bool changed) {
    return {changed, ImGui::IsItemDeactivatedAfterEdit()};
}

// Whether a drag field's typed text is a finite number, as ImGui reads it
// (leading and trailing blanks allowed).
bool finiteNumber(const char* text) {
    char* end = nullptr;
    double v = std::strtod(text, &end);
    if (end == text) return false;
    while (*end == ' ' || *end == '\t') ++end;
    return *end == '\0' && std::isfinite(v);
}

// One session of typing into a drag field (Ctrl+click or double-click):
// ImGui applies the text as it is typed, so the value before the session is
// kept to put back when the text entered is not a finite number ("1e99" then
// "1e999" had left 1e99 in the scene under the error), and what its
// scientific-number filter drops ("nan", "inf", letters) is collected to say
// so, where it used to vanish without a word.
struct TypingSession {
    double before = 0;
    std::string dropped;
    size_t reported = 0;  // of `dropped`, already said
    int frame = 0;        // the last frame the field was being typed into
};

std::unordered_map<ImGuiID, TypingSession>& typingSessions() {
    static std::unordered_map<ImGuiID, TypingSession> sessions;
    return sessions;
}

// What ImGui's CharsScientific filter lets into a number field.
bool keptByNumberFilter(ImWchar c) {
    return (c >= '0' && c <= '9') || c == '.' || c == '+' || c == '-' || c == '*' || c == '/' || c == 'e' || c == 'E';
}

struct TypedField {
    ImGuiID id = 0;
    std::optional<std::string> text;  // the typed text when the field is being typed into
};

// Called before the drag widget `id` that edits `value`: starts or continues
// its typing session and reads its text.
TypedField observeTyping(ImGuiID id, double value) {
    if (!ImGui::TempInputIsActive(id)) return {id, std::nullopt};
    const int frame = ImGui::GetFrameCount();
    TypingSession& session = typingSessions().try_emplace(id, TypingSession{value, {}, 0, frame}).first->second;
    if (session.frame < frame - 1) session = TypingSession{value, {}, 0, frame};  // a session left without ending
    session.frame = frame;
    for (ImWchar c : ImGui::GetIO().InputQueueCharacters) {
        if (c >= 32 && !keptByNumberFilter(c) && session.dropped.size() < 40)
            session.dropped += static_cast<char>(c < 127 ? c : '?');
    }
    ImGuiInputTextState* state = ImGui::GetInputTextState(id);
    if (!state || state->TextA.Size == 0) return {id, std::string()};
    return {id, std::string(state->TextA.Data)};
}

// Finishes a drag widget edit: a value made non-finite by typed text is put
// back; text that is not a finite number, once entered, puts back the value
// from before the typing session and is reported in `edit.notANumber`, as are
// characters the field refused while they are typed.
WidgetEdit checkedEdit(bool changed, const std::vector<TypedField>& typed, double* values, const double* before) {
    WidgetEdit edit = finishEdit(changed);
    for (size_t i = 0; i < typed.size(); ++i) {
        if (!std::isfinite(values[i])) {
            values[i] = before[i];
            edit.changed = false;
        }
        if (!typed[i].text) continue;
        auto found = typingSessions().find(typed[i].id);
        if (found == typingSessions().end()) continue;
        TypingSession& session = found->second;
        if (session.dropped.size() > session.reported) {
            edit.notANumber = session.dropped;
            session.reported = session.dropped.size();
        }
        if (!ImGui::IsItemDeactivated()) continue;
        if (!finiteNumber(typed[i].text->c_str())) {
            edit.notANumber = session.dropped.empty() ? *typed[i].text : session.dropped;
            edit.changed = edit.changed || values[i] != session.before;
            values[i] = session.before;
        }
        edit.finished = true;
        typingSessions().erase(found);
    }
    return edit;
}
}  // namespace

WidgetEdit dragReal(const char* label, double& value, double speed, double minimum, double maximum,
                    const char* format) {
    double before = value;
    std::vector<TypedField> typed{observeTyping(ImGui::GetID(label), value)};
    bool changed = ImGui::DragScalar(label, ImGuiDataType_Double, &value, static_cast<float>(speed),
                                     &minimum, &maximum, format);
    return checkedEdit(changed, typed, &value, &before);
}

WidgetEdit dragVec3(const char* label, glm::dvec3& value, double speed, double minimum, double maximum,
                    const char* format) {
    glm::dvec3 before = value;
    // DragScalarN's components are DragScalar("") under the ids label, then 0, 1, 2
    std::vector<TypedField> typed;
    ImGui::PushID(label);
    for (int i = 0; i < 3; ++i) {
        ImGui::PushID(i);
        typed.push_back(observeTyping(ImGui::GetID(""), value[i]));
        ImGui::PopID();
    }
    ImGui::PopID();
    bool changed = ImGui::DragScalarN(label, ImGuiDataType_Double, &value.x, 3, static_cast<float>(speed),
                                      &minimum, &maximum, format);
    return checkedEdit(changed, typed, &value.x, &before.x);
}

// The numbers are the scene's linear values; the swatch and its picker show
// them sRGB-encoded, as the render shows the colour (ImGui would show the
// linear numbers as if they were sRGB, too dark).
WidgetEdit colorEdit(const char* label, glm::dvec3& value) {
    float shown[3];
    for (int i = 0; i < 3; ++i) shown[i] = image::srgbFromLinear(static_cast<float>(value[i]));
    const float swatch = ImGui::GetFrameHeight(), gap = ImGui::GetStyle().ItemInnerSpacing.x;
    const float width = ImGui::CalcItemWidth();
    ImGui::PushID(label);
    bool picked = ImGui::ColorEdit3("##swatch", shown, ImGuiColorEditFlags_NoInputs | ImGuiColorEditFlags_NoLabel);
    ImGui::PopID();
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Click to pick; the numbers are linear, as the scene file holds them");
    WidgetEdit edit = finishEdit(picked);
    if (picked) {
        for (int i = 0; i < 3; ++i) value[i] = image::linearFromSrgb(shown[i]);
    }
    ImGui::SameLine(0, gap);
    ImGui::SetNextItemWidth(std::max(1.0f, width - swatch - gap));
    WidgetEdit typed = dragVec3(label, value, 0.005, 0.0, 1e6);
    return {edit.changed || typed.changed, edit.finished || typed.finished, typed.notANumber};
}

void commitEdit(Editor& editor, UiState& ui, const WidgetEdit& edit, const char* label,
                const std::function<void(scene::Scene&)>& change, std::string_view jsonPath) {
    if (!edit.notANumber.empty()) {
        std::string problem = (jsonPath.empty() ? std::string(label) : std::string(jsonPath)) + ": " +
                              io::quoted(shortened(edit.notANumber, 40)) + " is not a number (type a finite value such as 0.5)";
        ui.inspectorProblems = {problem};
        ui.error(problem);
    }
    if (edit.changed) {
        std::string key = std::to_string(ImGui::GetItemID());
        Problems problems = editor.apply(label, change, key);
        ui.inspectorProblems = problems;
        reportProblems(ui, problems);
    }
    if (edit.finished) {
        editor.endMerge();
    }
}

void reportProblems(UiState& ui, const Problems& problems) {
    for (const std::string& problem : problems) {
        ui.error(problem);
    }
}

void problemText(const std::string& problem) {
    if (problem.empty()) return;
    ImGui::PushStyleColor(ImGuiCol_Text, IM_COL32(255, 110, 100, 255));
    wrappedText(problem);
    ImGui::PopStyleColor();
}

}  // namespace sdfwb::ui
