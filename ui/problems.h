#pragma once
// The problems list (issue 13, item 8): every error the user met, tied to its
// cause, cleared when the cause is fixed, and the way to the cause.
//
// A refused edit's message starts with the JSON path of what was wrong
// ("root.children[0].radius: must be > 0 (got -1)"): that path is its cause.
// An error is resolved, and leaves the list, once the value at its cause
// changes (the user typed a good value) or the cause is gone (the node was
// deleted); a newer error of the same cause replaces it. Errors without a
// cause (a file that would not open, a failed export) stay until cleared.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "ui/editor.h"
#include "ui/ui_state.h"

namespace sdfwb::ui {

struct ProblemCause {
    std::string jsonPath;          // "root.children[0].radius"
    std::optional<NodePath> node;  // the deepest node on the path
    InspectorTab tab = InspectorTab::Node;  // where the cause is edited
};

// The cause a message names at its start; nullopt when it names none.
std::optional<ProblemCause> problemCause(std::string_view message);

// The value at a JSON path of the scene file (null when there is none).
nlohmann::ordered_json valueAt(const scene::Scene& scene, const ProblemCause& cause);

// Brings new messages under watch and drops the errors whose cause was fixed;
// cheap when the editor's revision has not changed. Call once a frame.
void updateProblems(UiState& ui, const Editor& editor);

// Selects the cause's node (or the scene's root for a setting) and brings its tab forward.
void goToCause(Editor& editor, UiState& ui, const ProblemCause& cause);

// The errors still open, newest first.
std::vector<const Message*> openErrors(const UiState& ui);

}  // namespace sdfwb::ui
