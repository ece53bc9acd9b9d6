#pragma once
// UI state that is not part of the scene: which backend the viewport uses,
// view options, and the messages shown to the user. Panels read and change it;
// the scene itself changes only through the Editor.

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "scene/node_kinds.h"
#include "ui/file_browser.h"
#include "ui/scene_image_check.h"

namespace sdfwb::ui {

enum class ViewBackend { Gl, Cpu };
enum class CompareMode { Off, SideBySide, Difference };
// The inspector's tabs, in their order on screen.
enum class InspectorTab { Node, Materials, Lights, Render, Environment, Library };
inline constexpr const char* kInspectorTabNames[] = {"node", "materials", "lights", "render", "environment", "library"};

// What the selection's handles in the viewport do (ui/transform_handles.h).
enum class HandleMode { Move, Rotate, Scale };
inline constexpr const char* kHandleModeNames[] = {"move", "rotate", "scale"};

struct Message {
    enum class Level { Info, Error };
    Level level = Level::Info;
    std::string text;
    // Kept by updateProblems (ui/problems.h):
    bool watched = false;       // revision and causeValue are set
    bool resolved = false;      // its cause was fixed or replaced by a newer error
    std::uint64_t revision = 0;  // the editor's revision when it was raised
    std::string causeValue;     // the value at its cause then, as JSON text
};

struct UiState {
    ViewBackend backend = ViewBackend::Gl;
    CompareMode compare = CompareMode::Off;
    bool showStats = true;       // statistics overlay on the viewport
    bool stepHeat = false;       // show the step-count heat image instead of colour
    bool showThumbnails = true;  // per-node thumbnails in the scene tree
    bool showProblems = false;   // the Problems window
    bool pixelReadout = true;    // distance, steps and node under the cursor, over the viewport
    HandleMode handles = HandleMode::Move;
    // A tab to bring to the front on the next frame (scripts), then cleared.
    std::optional<InspectorTab> showTab;

    // Newest last; the status bar shows the newest while it is current, the
    // Problems window the errors not yet resolved.
    std::vector<Message> messages;
    std::uint64_t problemsCheckedAt = 0;  // the editor revision updateProblems last checked
    // Problems of the last refused inspector edit, shown inline under it.
    std::vector<std::string> inspectorProblems;
    // The environment tab's image files, checked on a worker when they change.
    std::shared_ptr<SceneImageCheck> imageCheck = std::make_shared<SceneImageCheck>();
    // The thumbnail texture of the image file named at a JSON path, or null;
    // the window sets it (ImageThumbnails), tests may leave it empty.
    std::function<void*(const std::string& key)> imageThumbnail;
    // Lists a folder for the image picker (app/user_files/folder_listing.h);
    // the window sets it, tests may leave it empty (nothing listed).
    FolderLister listFolder;
    // The image picker: the JSON path of the field it chooses a file for ("" when closed).
    std::string imagePickerKey;
    FileBrowser imagePicker{{".png", ".jpg", ".jpeg", ".tif", ".tiff", ".exr"}};

    // Formulas being typed in the Add menu, by node kind name.
    std::map<std::string, std::string> addFormulaDrafts;

    // Name typed for "save the selection to the primitive library".
    std::string libraryName;

    // A subtree being dragged in the scene tree (thumbnails pause meanwhile).
    bool draggingNode = false;

    void info(std::string text) { add(Message::Level::Info, std::move(text)); }
    void error(std::string text) { add(Message::Level::Error, std::move(text)); }
    void add(Message::Level level, std::string text) {
        Message m;
        m.level = level;
        m.text = std::move(text);
        messages.push_back(std::move(m));
    }
};

}  // namespace sdfwb::ui
