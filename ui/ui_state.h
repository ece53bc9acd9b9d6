#pragma once
// UI state that is not part of the scene: which backend the viewport uses,
// view options, and the messages shown to the user. Panels read and change it;
// the scene itself changes only through the Editor.

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "scene/node_kinds.h"

namespace sdfwb::ui {

enum class ViewBackend { Gl, Cpu };
enum class CompareMode { Off, SideBySide, Difference };
// The inspector's tabs, in their order on screen.
enum class InspectorTab { Node, Materials, Lights, Render, Environment, Library };
inline constexpr const char* kInspectorTabNames[] = {"node", "materials", "lights", "render", "environment", "library"};

struct Message {
    enum class Level { Info, Error };
    Level level = Level::Info;
    std::string text;
};

struct UiState {
    ViewBackend backend = ViewBackend::Gl;
    CompareMode compare = CompareMode::Off;
    bool showStats = true;       // statistics overlay on the viewport
    bool stepHeat = false;       // show the step-count heat image instead of colour
    bool showThumbnails = true;  // per-node thumbnails in the scene tree
    bool pixelReadout = true;    // distance, steps and node under the cursor, over the viewport
    // A tab to bring to the front on the next frame (scripts), then cleared.
    std::optional<InspectorTab> showTab;

    // Newest last; the status bar shows the newest, the log window all.
    std::vector<Message> messages;
    // Problems of the last refused inspector edit, shown inline under it.
    std::vector<std::string> inspectorProblems;

    // Formulas being typed in the Add menu, by node kind name.
    std::map<std::string, std::string> addFormulaDrafts;

    // Name typed for "save the selection to the primitive library".
    std::string libraryName;

    // A subtree being dragged in the scene tree (thumbnails pause meanwhile).
    bool draggingNode = false;

    void info(std::string text) { messages.push_back({Message::Level::Info, std::move(text)}); }
    void error(std::string text) { messages.push_back({Message::Level::Error, std::move(text)}); }
};

}  // namespace sdfwb::ui
