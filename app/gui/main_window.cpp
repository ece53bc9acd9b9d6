#include "app/gui/main_window.h"

#include <cmath>
#include <utility>

#include <imgui.h>
#include <imgui_stdlib.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "app/gui/file_actions.h"
#include "app/gui/viewport_panel.h"
#include "ui/long_text.h"
#include "ui/panels.h"
#include "ui/placement.h"
#include "ui/problems.h"
#include "ui/quality_panel.h"
#include "ui/view_camera.h"

namespace sdfwb::app::gui {
namespace {

constexpr float kSideWidth = 390.0f;      // the scene tree over the inspector, right of the viewport
constexpr float kTreeFraction = 0.46f;   // of the side column's height
constexpr float kProgressWidth = 330.0f;  // the render progress at the status bar's right end
constexpr ImGuiWindowFlags kPanelFlags =
    ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings;

void undo(AppState& app) {
    if (!app.editor.undo()) app.ui.info("nothing to undo");
}
void redo(AppState& app) {
    if (!app.editor.redo()) app.ui.info("nothing to redo");
}
void duplicateSelection(AppState& app) {
    if (app.editor.selection()) ui::reportProblems(app.ui, ui::duplicatePlaced(app.editor, *app.editor.selection()));
}
void deleteSelection(AppState& app) {
    if (app.editor.selection()) ui::reportProblems(app.ui, app.editor.remove(*app.editor.selection()));
}

void frameSelected(AppState& app) {
    if (!app.editor.selection()) return;
    if (std::optional<scene::Camera> framed = ui::frameSelectedCamera(app.editor.scene(), *app.editor.selection())) {
        app.editor.setView(*framed);
    } else {
        app.ui.info("the selection is unbounded: nothing to frame");
    }
}
void setPreset(AppState& app, ui::ViewPreset preset) {
    app.editor.setView(ui::presetCamera(app.editor.scene().camera, preset));
}
void orbitStep(AppState& app, double azimuth, double elevation) {
    const scene::Scene& s = app.editor.scene();
    app.editor.setView(ui::orbited(s.camera, s.environment, azimuth, elevation));
}

// The numeric keypad's views, as in Blender (Ctrl: the opposite side).
struct ViewKey {
    int key;
    bool ctrl;
    ui::ViewPreset preset;
    const char* menu;
    const char* shortcut;
};
constexpr ViewKey kViewKeys[] = {
    {GLFW_KEY_KP_1, false, ui::ViewPreset::Front, "Front view", "Keypad 1"},
    {GLFW_KEY_KP_1, true, ui::ViewPreset::Back, "Back view", "Ctrl+Keypad 1"},
    {GLFW_KEY_KP_3, false, ui::ViewPreset::Right, "Right view", "Keypad 3"},
    {GLFW_KEY_KP_3, true, ui::ViewPreset::Left, "Left view", "Ctrl+Keypad 3"},
    {GLFW_KEY_KP_7, false, ui::ViewPreset::Top, "Top view", "Keypad 7"},
    {GLFW_KEY_KP_7, true, ui::ViewPreset::Bottom, "Bottom view", "Ctrl+Keypad 7"},
};
constexpr double kOrbitKeyStep = 15.0;  // degrees per keypad 2, 4, 6, 8 press, as Blender's

// The view keys of the numeric keypad; false for any other key.
bool viewShortcut(AppState& app, const KeyPress& press, bool ctrl) {
    for (const ViewKey& view : kViewKeys) {
        if (view.key == press.key && view.ctrl == ctrl) {
            setPreset(app, view.preset);
            return true;
        }
    }
    switch (press.key) {
    case GLFW_KEY_KP_4: orbitStep(app, -kOrbitKeyStep, 0); return true;
    case GLFW_KEY_KP_6: orbitStep(app, kOrbitKeyStep, 0); return true;
    case GLFW_KEY_KP_8: orbitStep(app, 0, kOrbitKeyStep); return true;
    case GLFW_KEY_KP_2: orbitStep(app, 0, -kOrbitKeyStep); return true;
    case GLFW_KEY_KP_DECIMAL: frameSelected(app); return true;
    case GLFW_KEY_HOME: frameAll(app); return true;
    default: return false;
    }
}

// The keyboard shortcuts besides the keypad's views: one table that the key
// handler runs and Help > Keyboard shortcuts lists.
struct Shortcut {
    int key;
    bool ctrl, shift;
    bool anyShift;  // Shift held or not
    const char* keys;
    const char* what;
    void (*run)(AppState&);
};
constexpr Shortcut kShortcuts[] = {
    {GLFW_KEY_Z, true, false, false, "Ctrl+Z", "Undo", [](AppState& a) { undo(a); }},
    {GLFW_KEY_Z, true, true, false, "Ctrl+Shift+Z", "Redo", [](AppState& a) { redo(a); }},
    {GLFW_KEY_Y, true, false, false, "Ctrl+Y", "Redo", [](AppState& a) { redo(a); }},
    {GLFW_KEY_N, true, false, false, "Ctrl+N", "New scene", [](AppState& a) { request(a, {PendingAction::Kind::New, {}}); }},
    {GLFW_KEY_O, true, false, false, "Ctrl+O", "Open...", [](AppState& a) { openDialog(a, FileDialogState::Purpose::Open); }},
    {GLFW_KEY_S, true, false, false, "Ctrl+S", "Save", [](AppState& a) { saveOrAsk(a); }},
    {GLFW_KEY_S, true, true, false, "Ctrl+Shift+S", "Save as...", [](AppState& a) { openDialog(a, FileDialogState::Purpose::SaveAs); }},
    {GLFW_KEY_E, true, false, true, "Ctrl+E", "Export snapshot...", [](AppState& a) { a.snapshot.dialogOpen = true; }},
    {GLFW_KEY_Q, true, false, true, "Ctrl+Q", "Quit", [](AppState& a) { request(a, {PendingAction::Kind::Quit, {}}); }},
    {GLFW_KEY_D, true, false, true, "Ctrl+D", "Duplicate the selection", [](AppState& a) { duplicateSelection(a); }},
    {GLFW_KEY_DELETE, false, false, true, "Del", "Delete the selection", [](AppState& a) { deleteSelection(a); }},
    {GLFW_KEY_1, true, false, true, "Ctrl+1", "GLSL backend", [](AppState& a) { a.ui.backend = ui::ViewBackend::Gl; }},
    {GLFW_KEY_2, true, false, true, "Ctrl+2", "CPU backend", [](AppState& a) { a.ui.backend = ui::ViewBackend::Cpu; }},
    {GLFW_KEY_G, false, false, true, "G", "Move handles", [](AppState& a) { a.ui.handles = ui::HandleMode::Move; }},
    {GLFW_KEY_R, false, false, true, "R", "Rotate handles", [](AppState& a) { a.ui.handles = ui::HandleMode::Rotate; }},
    {GLFW_KEY_S, false, false, true, "S", "Scale handles", [](AppState& a) { a.ui.handles = ui::HandleMode::Scale; }},
    {GLFW_KEY_F, false, false, true, "F", "Frame all (also Home)", [](AppState& a) { frameAll(a); }},
    {GLFW_KEY_H, false, false, true, "H", "Step heat view on or off", [](AppState& a) { a.ui.stepHeat = !a.ui.stepHeat; }},
    {GLFW_KEY_F12, false, false, true, "F12", "Save the window as PNG", [](AppState& a) { saveWindowPicture(a); }},
};

// How the mouse works in the viewport, for Help > Keyboard shortcuts.
constexpr const char* kMouseHelp[][2] = {
    {"Left drag", "Orbit the camera (a view change: not an undo step)"},
    {"Right or middle drag", "Pan"},
    {"Wheel", "Zoom"},
    {"Click", "Select what the pixel shows (the ground or sky: nothing)"},
    {"Drag a handle", "Move, rotate or scale the selection, one undo step; Ctrl snaps"},
};

void shortcutsWindow(AppState& app) {
    if (!app.showShortcuts) return;
    ImGui::SetNextWindowSize(ImVec2(520, 560), ImGuiCond_FirstUseEver);
    if (ImGui::Begin("Keyboard shortcuts", &app.showShortcuts)) {
        auto rows = [](const char* id, auto each) {
            if (!ImGui::BeginTable(id, 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit)) return;
            each();
            ImGui::EndTable();
        };
        auto row = [](const char* keys, const char* what) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(keys);
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(what);
        };
        ImGui::TextDisabled("Keys (not while typing in a field)");
        rows("keys", [&] {
            for (const Shortcut& s : kShortcuts) row(s.keys, s.what);
            row("Home", "Frame all");
            row("Keypad .", "Frame the selection");
            for (const ViewKey& v : kViewKeys) row(v.shortcut, v.menu);
            row("Keypad 4, 6, 8, 2", "Orbit in 15 degree steps");
        });
        ImGui::Separator();
        ImGui::TextDisabled("Mouse in the viewport");
        rows("mouse", [&] {
            for (const auto& m : kMouseHelp) row(m[0], m[1]);
        });
    }
    ImGui::End();
}

// Where the documentation is, relative to the source tree.
constexpr const char* kDocs[][2] = {
    {"docs/gui.md", "The workbench window"},
    {"docs/gui-script.md", "GUI scripts (--script)"},
    {"docs/scene-format.md", "The scene file format"},
    {"docs/expression-language.md", "Formulas of sdf nodes"},
    {"docs/implicit-surfaces.md", "Implicit and polynomial surfaces"},
    {"docs/rendering.md", "Rendering and the two backends"},
    {"docs/large-scenes.md", "Large scenes and spatial pruning"},
    {"docs/speed-vs-error.md", "Quality settings: speed against error"},
    {"README.md", "Commands (render, mesh, compare, ...)"},
};

void menuBar(AppState& app) {
    if (!ImGui::BeginMainMenuBar()) return;
    if (ImGui::BeginMenu("File")) {
        if (ImGui::MenuItem("New", "Ctrl+N")) request(app, {PendingAction::Kind::New, {}});
        if (ImGui::MenuItem("Open...", "Ctrl+O")) openDialog(app, FileDialogState::Purpose::Open);
        if (ImGui::BeginMenu("Open recent")) {
            if (ImGui::IsWindowAppearing()) app.recentFiles.refresh();  // files deleted since leave it
            // a copy: opening a file puts it at the list's front
            const std::vector<std::string> files = app.recentFiles.entries();
            for (const std::string& file : files) {
                if (ImGui::MenuItem(file.c_str())) request(app, {PendingAction::Kind::Open, file});
            }
            ImGui::EndMenu();
        }
        if (ImGui::MenuItem("Save", "Ctrl+S")) saveOrAsk(app);
        if (ImGui::MenuItem("Save as...", "Ctrl+Shift+S")) openDialog(app, FileDialogState::Purpose::SaveAs);
        ImGui::Separator();
        if (ImGui::MenuItem("Export snapshot...", "Ctrl+E")) app.snapshot.dialogOpen = true;
        if (ImGui::MenuItem("Export mesh...")) app.meshExport.dialogOpen = true;
        if (ImGui::MenuItem("Save window as PNG", "F12")) saveWindowPicture(app);
        ImGui::Separator();
        if (ImGui::MenuItem("Quit", "Ctrl+Q")) request(app, {PendingAction::Kind::Quit, {}});
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Edit")) {
        std::string undoLabel = "Undo " + std::string(app.editor.undoLabel());
        std::string redoLabel = "Redo " + std::string(app.editor.redoLabel());
        if (ImGui::MenuItem(undoLabel.c_str(), "Ctrl+Z", false, app.editor.canUndo())) undo(app);
        if (ImGui::MenuItem(redoLabel.c_str(), "Ctrl+Shift+Z / Ctrl+Y", false, app.editor.canRedo())) redo(app);
        ImGui::Separator();
        bool selected = app.editor.selection().has_value();
        if (ImGui::MenuItem("Duplicate", "Ctrl+D", false, selected)) duplicateSelection(app);
        if (ImGui::MenuItem("Delete", "Del", false, selected)) deleteSelection(app);
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Add")) {
        ui::drawAddMenuItems(app.editor, app.ui);
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Wrap")) {
        ui::drawWrapMenuItems(app.editor, app.ui);
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("View")) {
        if (ImGui::MenuItem("GLSL backend", "Ctrl+1", app.ui.backend == ui::ViewBackend::Gl)) app.ui.backend = ui::ViewBackend::Gl;
        if (ImGui::MenuItem("CPU backend", "Ctrl+2", app.ui.backend == ui::ViewBackend::Cpu)) app.ui.backend = ui::ViewBackend::Cpu;
        ImGui::Separator();
        if (ImGui::MenuItem("Compare side by side", nullptr, app.ui.compare == ui::CompareMode::SideBySide)) {
            app.ui.compare = app.ui.compare == ui::CompareMode::SideBySide ? ui::CompareMode::Off : ui::CompareMode::SideBySide;
        }
        if (ImGui::MenuItem("Compare as difference", nullptr, app.ui.compare == ui::CompareMode::Difference)) {
            app.ui.compare = app.ui.compare == ui::CompareMode::Difference ? ui::CompareMode::Off : ui::CompareMode::Difference;
        }
        ImGui::MenuItem("Step heat view", "H", &app.ui.stepHeat);
        ImGui::MenuItem("Statistics overlay", nullptr, &app.ui.showStats);
        ImGui::MenuItem("Node thumbnails", nullptr, &app.ui.showThumbnails);
        ImGui::MenuItem("Pixel readout", nullptr, &app.ui.pixelReadout);
        ImGui::MenuItem("Polynomial (implicitize)", nullptr, &app.polynomial.open);
        ImGui::MenuItem("Problems", nullptr, &app.ui.showProblems);
        ImGui::Separator();
        if (ImGui::MenuItem("Frame all", "Home, F")) frameAll(app);
        if (ImGui::MenuItem("Frame selected", "Keypad .", false, app.editor.selection().has_value())) frameSelected(app);
        for (const ViewKey& view : kViewKeys) {
            if (ImGui::MenuItem(view.menu, view.shortcut)) setPreset(app, view.preset);
        }
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Help")) {
        if (ImGui::MenuItem("Keyboard shortcuts")) app.showShortcuts = true;
        ImGui::Separator();
        ImGui::TextDisabled("Documentation (in the source tree; click to copy the path)");
        for (const auto& doc : kDocs) {
            if (ImGui::MenuItem(doc[1], doc[0])) ImGui::SetClipboardText(doc[0]);
        }
        ImGui::Separator();
        ImGui::TextDisabled("sdf-workbench --help lists the commands");
        ImGui::EndMenu();
    }
    ImGui::EndMainMenuBar();
}

void treePanel(AppState& app, ImVec2 origin, float height) {
    ImGui::SetNextWindowPos(origin);
    ImGui::SetNextWindowSize(ImVec2(kSideWidth, height));
    if (ImGui::Begin("Scene", nullptr, kPanelFlags)) {
        if (ImGui::Button("Add")) ImGui::OpenPopup("add");
        ImGui::SameLine();
        if (ImGui::Button("Wrap")) ImGui::OpenPopup("wrap");
        ImGui::SameLine();
        if (ImGui::Button("Duplicate")) duplicateSelection(app);
        ImGui::SameLine();
        if (ImGui::Button("Delete")) deleteSelection(app);
        if (ImGui::BeginPopup("add")) {
            ui::drawAddMenuItems(app.editor, app.ui);
            ImGui::EndPopup();
        }
        if (ImGui::BeginPopup("wrap")) {
            ui::drawWrapMenuItems(app.editor, app.ui);
            ImGui::EndPopup();
        }
        ImGui::BeginChild("tree", ImVec2(0, 0), true);
        ui::ThumbnailLookup thumbnails;
        if (app.ui.showThumbnails) {
            thumbnails = [&app](const ui::NodePath& path, const scene::Node& node) -> ImTextureID {
                return app.thumbnails->lookup(app.editor.scene(), app.editor.revision(), path, node);
            };
        }
        ui::drawSceneTree(app.editor, app.ui, thumbnails);
        ImGui::EndChild();
    }
    ImGui::End();
}

void inspectorPanel(AppState& app, ImVec2 origin, float height) {
    ImGui::SetNextWindowPos(origin);
    ImGui::SetNextWindowSize(ImVec2(kSideWidth, height));
    if (ImGui::Begin("Inspector", nullptr, kPanelFlags)) {
        if (ImGui::BeginTabBar("tabs")) {
            using Tab = ui::InspectorTab;
            auto tab = [&app](const char* label, Tab which) {
                ImGuiTabItemFlags flags = app.ui.showTab == which ? ImGuiTabItemFlags_SetSelected : 0;
                return ImGui::BeginTabItem(label, nullptr, flags);
            };
            if (tab("Node", Tab::Node)) {
                ui::drawInspector(app.editor, app.ui);
                ImGui::EndTabItem();
            }
            if (tab("Materials", Tab::Materials)) {
                ui::drawMaterialsPanel(app.editor, app.ui);
                ImGui::EndTabItem();
            }
            if (tab("Lights", Tab::Lights)) {
                ui::drawLightsPanel(app.editor, app.ui);
                ImGui::EndTabItem();
            }
            if (tab("Render", Tab::Render)) {
                ui::drawQualityPresets(app.editor, app.ui,
                                       app.measurements.forScene(app.editor.scene(), app.editor.revision()));
                ImGui::Separator();
                ui::drawRenderSettingsPanel(app.editor, app.ui);
                ImGui::EndTabItem();
            }
            if (tab("Environment", Tab::Environment)) {
                ui::drawEnvironmentPanel(app.editor, app.ui);
                ImGui::EndTabItem();
            }
            if (tab("Library", Tab::Library)) {
                ui::drawLibraryPanel(app.editor, app.ui, app.library);
                ImGui::EndTabItem();
            }
            app.ui.showTab.reset();
            ImGui::EndTabBar();
        }
    }
    ImGui::End();
}

// The newest message while it is current (an info, or an error no edit has
// passed yet), else how many problems are open; a click opens the Problems window.
void statusBar(AppState& app, ImVec2 origin, float width, float height) {
    ImGui::SetNextWindowPos(origin);
    ImGui::SetNextWindowSize(ImVec2(width, height));
    ui::updateProblems(app.ui, app.editor);  // this frame's messages, with this frame's edits
    if (ImGui::Begin("##status", nullptr, kPanelFlags | ImGuiWindowFlags_NoDecoration)) {
        const ui::Message* last = app.ui.messages.empty() ? nullptr : &app.ui.messages.back();
        size_t open = ui::openErrors(app.ui).size();
        bool current = last && !last->resolved &&
                       (last->level == ui::Message::Level::Info || last->revision == app.editor.revision());
        // clear of the progress text on the right, whatever the message's length
        const float room = width - kProgressWidth - 24;
        if (current) {
            bool error = last->level == ui::Message::Level::Error;
            ImGui::PushStyleColor(ImGuiCol_Text, error ? ImVec4(1, 0.45f, 0.4f, 1) : ImVec4(0.75f, 0.8f, 0.85f, 1));
            std::string more = open > 1 || (open == 1 && !error) ? "  (" + std::to_string(open) + " problems)" : "";
            ui::oneLineText(last->text + more, room);
            ImGui::PopStyleColor();
        } else if (open > 0) {
            ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1, 0.6f, 0.5f, 1));
            ui::oneLineText(std::to_string(open) +
                                (open == 1 ? " problem: click here to list it" : " problems: click here to list them"),
                            room);
            ImGui::PopStyleColor();
        } else {
            ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
            ui::oneLineText(
                "Drag in the viewport to orbit, right-drag to pan, wheel to zoom; drag a handle of the selection to "
                "move it.",
                room);
            ImGui::PopStyleColor();
        }
        if (ImGui::IsItemHovered() && open > 0) ImGui::SetTooltip("Click to list the problems");
        if (ImGui::IsItemClicked()) app.ui.showProblems = true;
        ImGui::SameLine(width - kProgressWidth);
        ImGui::TextDisabled("%s", app.viewport->stats().status.c_str());
    }
    ImGui::End();
}

// The export dialogs' last row: progress and Cancel while the export runs,
// else Export (`start`) and Close.
template <typename ExportJob, typename Start>
void exportDialogFooter(ExportJob& job, Start start) {
    if (job.running()) {
        ImGui::ProgressBar(static_cast<float>(job.progress()), ImVec2(360, 0));
        if (ImGui::Button("Cancel")) job.cancel();
        return;
    }
    if (ImGui::Button("Export")) start();
    ImGui::SameLine();
    if (ImGui::Button("Close")) {
        job.dialogOpen = false;
        ImGui::CloseCurrentPopup();
    }
}

void snapshotDialog(AppState& app) {
    SnapshotExport& snapshot = app.snapshot;
    if (snapshot.dialogOpen && !ImGui::IsPopupOpen("Export snapshot")) {
        snapshot.settings.width = app.editor.scene().render.width;
        snapshot.settings.height = app.editor.scene().render.height;
        snapshot.settings.aa = app.editor.scene().render.aa;
        ImGui::OpenPopup("Export snapshot");
    }
    if (!ImGui::BeginPopupModal("Export snapshot", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    SnapshotSettings& s = snapshot.settings;
    ImGui::BeginDisabled(snapshot.running());
    ImGui::SetNextItemWidth(360);
    ImGui::InputText("file (.png, .jpg, .tif or .exr)", &s.path);
    ImGui::SetNextItemWidth(200);
    ImGui::InputInt2("size", &s.width);
    ImGui::SetNextItemWidth(200);
    ImGui::SliderInt("AA", &s.aa, 1, scene::kMaxAa);
    int backend = s.gl ? 1 : 0;
    ImGui::RadioButton("CPU", &backend, 0);
    ImGui::SameLine();
    ImGui::RadioButton("GLSL", &backend, 1);
    s.gl = backend == 1;
    ImGui::EndDisabled();
    s.width = std::clamp(s.width, 1, scene::kMaxImageSize);
    s.height = std::clamp(s.height, 1, scene::kMaxImageSize);
    exportDialogFooter(snapshot, [&] {
        std::unique_ptr<glcontext::GlContext> shared;
        if (s.gl) shared = app.context->createShared();
        snapshot.start(app.editor.scene(), s, std::move(shared));
    });
    ImGui::EndPopup();
}

void meshExportDialog(AppState& app) {
    MeshExport& exporter = app.meshExport;
    if (exporter.dialogOpen && !ImGui::IsPopupOpen("Export mesh")) ImGui::OpenPopup("Export mesh");
    if (!ImGui::BeginPopupModal("Export mesh", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    MeshExportSettings& s = exporter.settings;
    ImGui::BeginDisabled(exporter.running());
    ImGui::SetNextItemWidth(360);
    ImGui::InputText("file (.stl, .obj or .ply)", &s.path);
    ImGui::SetNextItemWidth(200);
    ImGui::SliderInt("resolution", &s.resolution, mesh::kMinResolution, mesh::kMaxResolution);
    if (ImGui::IsItemHovered()) {
        ImGui::SetTooltip("Voxels along the longest side of the scene's bounds; the ground is left out");
    }
    ImGui::EndDisabled();
    s.resolution = std::clamp(s.resolution, mesh::kMinResolution, mesh::kMaxResolution);
    exportDialogFooter(exporter, [&] { exporter.start(app.editor.scene(), s); });
    ImGui::EndPopup();
}

}  // namespace

void saveWindowPicture(AppState& app) {
    // the next free name in the working directory, for bug reports and docs
    for (int i = 1;; ++i) {
        std::filesystem::path path = "sdf-workbench-window-" + std::to_string(i) + ".png";
        if (!std::filesystem::exists(path)) {
            app.screenshot = path;
            return;
        }
    }
}

void handleShortcuts(AppState& app) {
    std::vector<KeyPress> presses = std::exchange(app.keyPresses, {});
    if (ImGui::GetIO().WantTextInput) return;  // Ctrl+Z in a text field is the field's own undo
    for (const KeyPress& press : presses) {
        bool ctrl = press.mods & GLFW_MOD_CONTROL, shift = press.mods & GLFW_MOD_SHIFT;
        if (viewShortcut(app, press, ctrl)) continue;
        for (const Shortcut& s : kShortcuts) {
            if (s.key == press.key && s.ctrl == ctrl && (s.shift == shift || s.anyShift)) {
                s.run(app);
                break;
            }
        }
    }
}

void drawMainWindow(AppState& app) {
    menuBar(app);
    const ImGuiViewport* screen = ImGui::GetMainViewport();
    float menuHeight = ImGui::GetFrameHeight();
    float statusHeight = ImGui::GetFrameHeight() + 8;
    ImVec2 origin(screen->WorkPos.x, screen->Pos.y + menuHeight);
    float height = screen->Size.y - menuHeight - statusHeight;
    float width = screen->Size.x;
    float treeHeight = std::floor(height * kTreeFraction);
    treePanel(app, ImVec2(origin.x + width - kSideWidth, origin.y), treeHeight);
    inspectorPanel(app, ImVec2(origin.x + width - kSideWidth, origin.y + treeHeight), height - treeHeight);
    ImGui::SetNextWindowPos(origin);
    ImGui::SetNextWindowSize(ImVec2(width - kSideWidth, height));
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(4, 4));
    if (ImGui::Begin("Viewport", nullptr, kPanelFlags | ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse)) {
        drawViewportPanel(app);
    }
    ImGui::End();
    ImGui::PopStyleVar();
    statusBar(app, ImVec2(origin.x, origin.y + height), width, statusHeight);
    ui::drawPolynomialPanel(app.editor, app.ui, app.polynomial, origin,
                            ImVec2(origin.x + width - kSideWidth, origin.y + height));
    ui::drawProblemsWindow(app.editor, app.ui);
    shortcutsWindow(app);
    snapshotDialog(app);
    meshExportDialog(app);
    drawFileDialogs(app);
}

}  // namespace sdfwb::app::gui
