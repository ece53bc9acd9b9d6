#pragma once
// The GUI script language (docs/gui-script.md): one command a line, run
// through the same Editor as the UI, so undo works on scripted edits too.
//
// A script is parsed whole before it runs, so an unknown command or a wrong
// argument count stops it before anything happens; errors that depend on the
// scene (a path that leads nowhere, an invalid value) stop it when reached.
// Every error names the script and line: "demo.txt:4: unknown command ...".

#include <chrono>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "ui/editor.h"
#include "ui/polynomial_panel.h"
#include "ui/ui_state.h"

namespace sdfwb::ui {

struct ScriptCommand {
    int line = 0;                   // 1-based line in the script
    std::string name;               // "select", "set", ...
    std::vector<std::string> args;  // whitespace-separated; `set` keeps its value whole
    bool expectFailure = false;     // written `fails <command>`: the command must fail
};

// Throws std::runtime_error "<source>:<line>: <reason>" on the first bad line.
std::vector<ScriptCommand> parseScript(std::string_view text, const std::string& source);

// What the application does for a script: it reports idleness and performs
// the actions that need the window.
class ScriptHost {
public:
    virtual ~ScriptHost() = default;
    // Every render, shader compile and thumbnail for the current state is done.
    virtual bool idle() const = 0;
    // Saves the whole window as it is drawn at the end of this frame; returns
    // an error message, or "" when the request was accepted.
    virtual std::string requestScreenshot(const std::filesystem::path& path) = 0;
    // Saves the scene (and marks it saved); "" or the error.
    virtual std::string save(const std::filesystem::path& path) = 0;
    // Opens a scene file in place of the current one; "" or the error.
    virtual std::string open(const std::filesystem::path& path) = 0;
    // Writes the autosave as the interactive session's timer does; "" or the error.
    virtual std::string autosave() { return "autosave is not available here"; }
    // Loads the autosave as the restore offer's Restore button does; "" or the error.
    virtual std::string restoreAutosave() { return "no autosave can be restored here"; }
    virtual void quit() = 0;
    // The polynomial panel the `polynomial` commands drive.
    virtual PolynomialPanelState& polynomialPanel() = 0;
    // The viewport's image size in pixels ({0, 0}: none; `pick` then uses the
    // scene's render size).
    virtual std::pair<int, int> viewSize() const { return {0, 0}; }
};

enum class ScriptStatus { Running, Finished, Failed };

class ScriptRunner {
public:
    ScriptRunner(std::vector<ScriptCommand> commands, std::string source);

    // Runs at most one command per call (the app calls it once a frame, so
    // every command's effect is drawn before the next one looks at it);
    // waiting commands return Running until their condition holds.
    ScriptStatus step(Editor& editor, UiState& ui, ScriptHost& host);

    // The current command waits for background work (`wait idle`,
    // `screenshot`, `polynomial run`): until it ends, the window may draw
    // at its own pace instead of a frame right after another.
    bool waitsForBackground() const { return waitingIdle_ || polynomialRunning_; }

    // "<source>:<line>: <reason>" after Failed.
    const std::string& error() const { return error_; }

    // How long `wait idle` and `screenshot` wait for idleness.
    std::chrono::seconds idleTimeout{300};

private:
    ScriptStatus fail(const ScriptCommand& command, const std::string& reason);
    // An edit the editor refused. When the script expects that, the problems
    // are first reported as the panels report them, so they reach the status
    // bar and the Problems list (ui/problems.h) as a user's would.
    ScriptStatus refuse(const ScriptCommand& command, UiState& ui, const Problems& problems);
    ScriptStatus run(const ScriptCommand& command, Editor& editor, UiState& ui, ScriptHost& host);
    bool waitIdle(const ScriptCommand& command, ScriptHost& host);
    ScriptStatus runPolynomial(const ScriptCommand& command, Editor& editor, UiState& ui, ScriptHost& host);

    std::vector<ScriptCommand> commands_;
    std::string source_;
    size_t next_ = 0;
    int framesLeft_ = -1;  // `wait N` in progress when >= 0
    bool waitingIdle_ = false;
    bool polynomialRunning_ = false;  // `polynomial run` started the job
    std::chrono::steady_clock::time_point waitStart_;
    std::string error_;
};

// The script for `--screenshot OUT --frames N`.
std::string screenshotScript(const std::string& output, int frames);

}  // namespace sdfwb::ui
