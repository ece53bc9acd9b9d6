#pragma once
// What the GUI holds while it runs: the edit layer and UI state (ui/), the
// renderers (viewport, thumbnails), the file state and script. Plain data
// with the parts that own resources; the behaviour lives in functions per
// concern (main_window.cpp, viewport_panel.cpp, file_actions.cpp, ...).

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/gui/glfw_context.h"
#include "app/gui/image_thumbnails.h"
#include "app/gui/mesh_export.h"
#include "app/gui/snapshot_export.h"
#include "app/gui/thumbnails.h"
#include "app/gui/view_selection.h"
#include "app/gui/viewport.h"
#include "app/user_files/primitive_folder.h"
#include "app/user_files/recent_files.h"
#include "tradeoff/measurements.h"
#include "ui/editor.h"
#include "ui/file_browser.h"
#include "ui/polynomial_panel.h"
#include "ui/script.h"
#include "ui/transform_handles.h"
#include "ui/ui_state.h"

struct GLFWwindow;

namespace sdfwb::app::gui {

// An action that replaces or ends the document, held while the user answers
// "save changes?".
struct PendingAction {
    enum class Kind { None, New, Open, Quit } kind = Kind::None;
    std::filesystem::path path;  // Open
};

struct FileDialogState {
    enum class Purpose { None, Open, SaveAs } purpose = Purpose::None;
    ui::FileBrowser browser{{".json"}};
};

struct FileState {
    std::filesystem::path current;  // "" for an unsaved new scene
    FileDialogState dialog;
    PendingAction pending;
    bool askUnsaved = false;    // the "save changes?" prompt is open
    bool offerRestore = false;  // the autosave restore prompt is open
    double lastAutosave = 0;    // glfwGetTime() of the last autosave check
};

struct ViewRequest {
    int width = 0, height = 0;  // framebuffer pixels of the image area
    bool interacting = false;   // a camera drag or a slider drag is active
};

// A key press as GLFW reported it (GLFW_KEY_*, GLFW_MOD_* bits). Presses are
// queued by the key callback rather than read from ImGui's key state, which in
// 1.86 loses a press and release that arrive within one frame.
struct KeyPress {
    int key = 0;
    int mods = 0;
};

struct AppState {
    GLFWwindow* window = nullptr;
    std::unique_ptr<GlfwContext> context;
    ui::Editor editor;
    ui::UiState ui;
    ui::PolynomialPanelState polynomial;  // View > Polynomial
    PrimitiveFolder library;              // the Library tab's files, listed once
    RecentFiles recentFiles;              // File > Open recent
    tradeoff::MeasurementLookup measurements{tradeoff::defaultCacheDirectory()};  // Render tab's error estimate
    std::unique_ptr<Viewport> viewport;
    std::unique_ptr<Thumbnails> thumbnails;
    std::unique_ptr<ImageThumbnails> imageThumbnails;  // beside the image file fields
    SnapshotExport snapshot;
    MeshExport meshExport;  // File > Export mesh
    FileState files;
    ViewRequest view;
    ViewPicks picks;                   // the viewport's readout and click picks
    ui::HandleDrag handleDrag;         // a move, rotate or scale handle held in the viewport
    bool pressTookHandle = false;      // the last press in the viewport was on a handle (not a click to select)
    bool showShortcuts = false;        // Help > Keyboard shortcuts
    std::vector<KeyPress> keyPresses;  // since the last frame
    std::uint64_t lastRevision = 0;    // the editor's revision seen last frame
    double lastChange = 0;             // glfwGetTime() when it last changed
    std::optional<ui::ScriptRunner> script;
    bool scripted = false;                            // scripts and screenshot runs: no prompts, no autosave
    std::size_t messagesPrinted = 0;                  // of ui.messages, written to stdout in scripted runs
    std::string viewportErrorLogged;                  // the viewport's error last put in the log
    std::optional<std::filesystem::path> screenshot;  // to save at the end of this frame
    bool quit = false;
    int exitCode = 0;
    std::string windowTitleShown;  // what glfwSetWindowTitle was last given
    double frameStart = 0;         // glfwGetTime() when the last frame began its work
    float frameSeconds = 0;
    float slowestFrameSeconds = 0;  // over the last few seconds
    double slowestFrameSince = 0;   // glfwGetTime() when that window started
};

}  // namespace sdfwb::app::gui
