#include "app/gui/file_actions.h"

#include <algorithm>

#include <imgui.h>
#include <imgui_stdlib.h>

#include "app/user_files/folder_listing.h"
#include "app/user_files/user_paths.h"
#include "io/atomic_file.h"
#include "program/scene_images.h"
#include "scene/scene_json.h"

namespace sdfwb::app::gui {

namespace fs = std::filesystem;

std::string openScene(AppState& app, const fs::path& path) {
    try {
        app.editor.reset(scene::loadSceneFile(path));
        app.files.current = path;
        app.recentFiles.remember(path.string());
        app.ui.info("opened " + path.string());
        return "";
    } catch (const scene::SceneError& error) {
        for (const std::string& problem : error.problems()) app.ui.error(problem);
        return error.problems().empty() ? error.what() : error.problems().front();
    }
}

std::string saveScene(AppState& app, const fs::path& path) {
    try {
        // saved elsewhere, the scene's image files keep their names relative to its new folder
        scene::Scene moved = app.editor.scene();
        program::moveSceneDirectory(moved, fs::absolute(path).parent_path());
        if (moved != app.editor.scene()) {
            // refused, the old names would be saved where they name other files (or none)
            ui::Problems refused = app.editor.apply("Save in another folder", [&](scene::Scene& s) { s = moved; });
            if (!refused.empty()) throw std::runtime_error("cannot save " + path.string() + ": " + refused.front());
        }
        scene::saveSceneFile(app.editor.scene(), path);
        app.editor.setDirectory(fs::absolute(path).parent_path().string());
    } catch (const std::exception& error) {
        app.ui.error(error.what());
        return error.what();
    }
    app.editor.markSaved();
    app.files.current = path;
    app.recentFiles.remember(path.string());
    removeAutosave();
    app.ui.info("saved " + path.string());
    return "";
}

namespace {

void perform(AppState& app, const PendingAction& action) {
    switch (action.kind) {
    case PendingAction::Kind::New:
        app.editor.reset(scene::Scene{});
        app.files.current.clear();
        break;
    case PendingAction::Kind::Open: openScene(app, action.path); break;
    case PendingAction::Kind::Quit: app.quit = true; break;
    case PendingAction::Kind::None: break;
    }
}

}  // namespace

void request(AppState& app, PendingAction action) {
    if (!app.editor.dirty() || app.scripted) {
        perform(app, action);
        return;
    }
    app.files.pending = std::move(action);
    app.files.askUnsaved = true;
}

void openDialog(AppState& app, FileDialogState::Purpose purpose) {
    FileDialogState& dialog = app.files.dialog;
    dialog.purpose = purpose;
    fs::path start = app.files.current.empty() ? fs::current_path() : fs::absolute(app.files.current).parent_path();
    dialog.browser.open(
        listFolder, start,
        app.files.current.empty() ? (start / "scene.json").string() : fs::absolute(app.files.current).string());
}

void saveOrAsk(AppState& app) {
    if (app.files.current.empty()) {
        openDialog(app, FileDialogState::Purpose::SaveAs);
    } else {
        saveScene(app, app.files.current);
    }
}

namespace {

void drawFileBrowser(AppState& app) {
    FileDialogState& dialog = app.files.dialog;
    const char* title = dialog.purpose == FileDialogState::Purpose::Open ? "Open scene" : "Save scene as";
    if (dialog.purpose != FileDialogState::Purpose::None && !ImGui::IsPopupOpen(title)) ImGui::OpenPopup(title);
    ImGui::SetNextWindowSize(ImVec2(620, 420), ImGuiCond_Appearing);
    if (!ImGui::BeginPopupModal(title)) return;
    bool enter = dialog.browser.draw(ImGui::GetFrameHeightWithSpacing());
    bool accept = ImGui::Button(dialog.purpose == FileDialogState::Purpose::Open ? "Open" : "Save") || enter;
    ImGui::SameLine();
    bool cancel = ImGui::Button("Cancel") || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape));
    if (accept) {
        if (dialog.purpose == FileDialogState::Purpose::Open) {
            request(app, {PendingAction::Kind::Open, dialog.browser.path});
        } else {
            saveScene(app, dialog.browser.path);
        }
    }
    if (accept || cancel) {
        dialog.purpose = FileDialogState::Purpose::None;
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
}

void drawUnsavedPrompt(AppState& app) {
    if (app.files.askUnsaved && !ImGui::IsPopupOpen("Unsaved changes")) ImGui::OpenPopup("Unsaved changes");
    if (!ImGui::BeginPopupModal("Unsaved changes", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    ImGui::Text("The scene has unsaved changes. Save them first?");
    bool close = false;
    if (ImGui::Button("Save")) {
        if (app.files.current.empty()) {
            openDialog(app, FileDialogState::Purpose::SaveAs);
            app.files.pending = {};
        } else if (saveScene(app, app.files.current).empty()) {
            perform(app, app.files.pending);
        }
        close = true;
    }
    ImGui::SameLine();
    if (ImGui::Button("Discard changes")) {
        perform(app, app.files.pending);
        close = true;
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) close = true;
    if (close) {
        app.files.askUnsaved = false;
        app.files.pending = {};
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
}

void drawRestorePrompt(AppState& app) {
    if (app.files.offerRestore && !ImGui::IsPopupOpen("Restore unsaved work?"))
        ImGui::OpenPopup("Restore unsaved work?");
    // centred and no larger than the window, whatever its size now
    const ImGuiViewport* screen = ImGui::GetMainViewport();
    ImGui::SetNextWindowPos(
        ImVec2(screen->WorkPos.x + screen->WorkSize.x * 0.5f, screen->WorkPos.y + screen->WorkSize.y * 0.5f),
        ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSizeConstraints(ImVec2(0, 0), ImVec2(screen->WorkSize.x - 16, screen->WorkSize.y - 16));
    if (!ImGui::BeginPopupModal("Restore unsaved work?", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    ImGui::PushTextWrapPos(std::min(screen->WorkSize.x - 48, 560.0f));
    ImGui::TextWrapped("A previous session ended with unsaved changes. Restore them from %s?", autosavePath().c_str());
    ImGui::PopTextWrapPos();
    bool close = false;
    if (ImGui::Button("Restore")) {
        restoreAutosave(app);
        close = true;
    }
    ImGui::SameLine();
    if (ImGui::Button("Discard")) {
        removeAutosave();
        close = true;
    }
    if (close) {
        app.files.offerRestore = false;
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
}

}  // namespace

void drawFileDialogs(AppState& app) {
    drawFileBrowser(app);
    drawUnsavedPrompt(app);
    drawRestorePrompt(app);
}

fs::path autosavePath() { return stateDirectory() / "autosave.json"; }

namespace {
// Beside the autosave, the file the work was opened from or last saved to
// (absent for a new scene): restored work comes back as that file's unsaved
// changes, under its name, and Save writes it there.
fs::path autosaveSourcePath() { return stateDirectory() / "autosave-source.txt"; }
}  // namespace

void autosaveTick(AppState& app, double now) {
    constexpr double kInterval = 60.0;
    if (app.scripted || now - app.files.lastAutosave < kInterval) return;
    app.files.lastAutosave = now;
    if (app.editor.dirty()) writeAutosave(app);
}

std::string writeAutosave(AppState& app) {
    try {
        fs::create_directories(autosavePath().parent_path());
        scene::saveSceneFile(app.editor.scene(), autosavePath());
        if (app.files.current.empty()) {
            std::error_code ignored;
            fs::remove(autosaveSourcePath(), ignored);
        } else {
            io::writeTextAtomically(autosaveSourcePath(), fs::absolute(app.files.current).string());
        }
    } catch (const std::exception& error) {
        std::string problem = std::string("autosave failed: ") + error.what();
        app.ui.error(problem);
        return problem;
    }
    app.ui.info("autosaved to " + autosavePath().string());
    return "";
}

std::string restoreAutosave(AppState& app) {
    try {
        app.editor.reset(scene::loadSceneFile(autosavePath()));
    } catch (const scene::SceneError& error) {
        std::string problem = error.problems().empty() ? error.what() : error.problems().front();
        app.ui.error("cannot restore the autosave: " + problem);
        return problem;
    }
    app.files.current.clear();
    try {
        if (fs::exists(autosaveSourcePath())) app.files.current = io::readTextFile(autosaveSourcePath(), 1 << 16);
    } catch (const std::exception&) {
        // the work is restored all the same, as a new scene
    }
    // restored work is unsaved work, and its file names are relative to its
    // own file's folder (an untitled scene's: the working directory), not the autosave's
    app.editor.apply("Restore", [](scene::Scene&) {});
    app.editor.setDirectory(app.files.current.empty() ? std::string() : app.files.current.parent_path().string());
    app.files.offerRestore = false;
    app.ui.info("restored unsaved work" +
                (app.files.current.empty() ? std::string() : " of " + app.files.current.string()) + " from " +
                autosavePath().string());
    return "";
}

void removeAutosave() {
    std::error_code error;
    fs::remove(autosavePath(), error);
    fs::remove(autosaveSourcePath(), error);
}

std::string windowTitle(const AppState& app) {
    std::string name = app.files.current.empty() ? "untitled" : app.files.current.filename().string();
    return "SDF Workbench - " + name + (app.editor.dirty() ? " *" : "");
}

}  // namespace sdfwb::app::gui
