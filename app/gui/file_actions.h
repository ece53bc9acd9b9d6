#pragma once
// Files: New, Open, Save, Save As, recent files, the built-in file dialog,
// the "save changes?" prompt before New, Open and Quit, and autosave with a
// restore offer on the next start (off for scripted runs).

#include <filesystem>
#include <string>

#include "app/gui/app_state.h"

namespace sdfwb::app::gui {

// Opens `path` now (no prompt); "" or the error (also shown in the UI).
std::string openScene(AppState& app, const std::filesystem::path& path);
// Saves to `path` (atomically) and makes it the current file; "" or the error.
std::string saveScene(AppState& app, const std::filesystem::path& path);

// Requests New/Open/Quit: runs it at once when there are no unsaved changes,
// otherwise asks first.
void request(AppState& app, PendingAction action);
// Save to the current file, or ask for a path when there is none.
void saveOrAsk(AppState& app);
void openDialog(AppState& app, FileDialogState::Purpose purpose);

// Draws the dialog and prompts that are open; call once per frame.
void drawFileDialogs(AppState& app);

// Autosave: every minute while there are unsaved changes.
std::filesystem::path autosavePath();
void autosaveTick(AppState& app, double now);
// Writes the autosave now (the timer's write); "" or the error (also shown).
std::string writeAutosave(AppState& app);
// Replaces the scene by the autosave as unsaved work (the restore offer's
// Restore button); "" or the error (also shown), the scene then unchanged.
std::string restoreAutosave(AppState& app);
// On a clean exit or after a save the recovery file is no longer needed.
void removeAutosave();

// "SDF Workbench - name.json *"
std::string windowTitle(const AppState& app);

}  // namespace sdfwb::app::gui
