#include "app/gui/gui_command.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include "glcontext/gl_functions.h"
#define GLFW_INCLUDE_NONE  // GL/gl.h would hide glcorearb.h's GL 1.x typedefs
#include <GLFW/glfw3.h>

#include "app/command_errors.h"
#include "app/gui/app_state.h"
#include "app/gui/file_actions.h"
#include "app/gui/gl_debug_log.h"
#include "app/gui/key_gate.h"
#include "app/gui/main_window.h"
#include "app/gui/window_capture.h"
#include "app/output_paths.h"
#include "app/scene_source.h"
#include "app/user_files/folder_listing.h"
#include "app/user_files/recent_files.h"
#include "image/image_io.h"
#include "io/atomic_file.h"
#include "scene/scene_json.h"

namespace sdfwb::app::gui {

namespace {

class Host final : public ui::ScriptHost {
public:
    explicit Host(AppState& app) : app_(app) {}
    bool idle() const override {
        return app_.viewport->idle() && (!app_.ui.showThumbnails || app_.thumbnails->idle()) &&
               !app_.ui.imageCheck->pending() && !app_.snapshot.running() && !app_.meshExport.running();
    }
    std::string requestScreenshot(const std::filesystem::path& path) override {
        app_.screenshot = path;
        return "";
    }
    std::string save(const std::filesystem::path& path) override { return saveScene(app_, path); }
    std::string open(const std::filesystem::path& path) override { return openScene(app_, path); }
    std::string autosave() override { return writeAutosave(app_); }
    std::string restoreAutosave() override {
        if (!std::filesystem::exists(autosavePath())) return "no autosave at " + autosavePath().string();
        return gui::restoreAutosave(app_);
    }
    void quit() override { app_.quit = true; }
    ui::PolynomialPanelState& polynomialPanel() override { return app_.polynomial; }
    std::pair<int, int> viewSize() const override { return {app_.view.width, app_.view.height}; }

private:
    AppState& app_;
};

std::string glfwErrorText;

KeyGate keyGate;  // one window per process

// Installed after ImGui's backend: shortcuts see every press at once, ImGui
// sees them through the gate.
void onKey(GLFWwindow* window, int key, int scancode, int action, int mods) {
    auto* app = static_cast<AppState*>(glfwGetWindowUserPointer(window));
    if (app && action != GLFW_RELEASE) app->keyPresses.push_back({key, mods});
    keyGate.onKey(window, key, scancode, action, mods);
}

void onChar(GLFWwindow* window, unsigned int codepoint) { keyGate.onChar(window, codepoint); }

void setUpStyle(float scale) {
    ImGui::StyleColorsDark();
    ImGuiStyle& style = ImGui::GetStyle();
    style.WindowRounding = 0;
    style.FrameRounding = 3;
    style.GrabRounding = 3;
    style.WindowBorderSize = 1;
    style.ItemSpacing = ImVec2(6, 4);
    style.IndentSpacing = 14;
    style.ScaleAllSizes(scale);
    ImFontConfig font;
    font.SizePixels = 13.0f * scale;
    ImGui::GetIO().Fonts->AddFontDefault(&font);
}

// A GL failure (a shader refused or that does not build) goes to the log
// once, besides the viewport's own line.
void noteViewportError(AppState& app) {
    const std::string& error = app.viewport->error();
    if (error == app.viewportErrorLogged) return;
    app.viewportErrorLogged = error;
    if (!error.empty()) app.ui.error(app.viewport->errorLine());
}

// Scripted runs write every message the status bar shows to the standard
// output, so that whoever runs a script sees what a user would.
void printNewMessages(AppState& app) {
    for (; app.messagesPrinted < app.ui.messages.size(); ++app.messagesPrinted) {
        const ui::Message& message = app.ui.messages[app.messagesPrinted];
        std::cout << "sdf-workbench gui: " << (message.level == ui::Message::Level::Error ? "error: " : "")
                  << message.text << std::endl;
    }
}

// While background work runs (renders, an implicitization's live progress)
// and nothing else needs frames, the window draws at most this often. On
// llvmpipe a frame of the window costs about 20 ms of processor time over the
// driver's threads, so an unpaced loop took the cores the render needs, all
// the more since the render's threads yield to the window's (jobs/thread_priority.h).
// Input ends the wait at once, so the window answers as quickly as before.
constexpr double kBackgroundFrameSeconds = 1.0 / 30;

void runFrame(AppState& app, Host& host) {
    // a script's next command (one a frame), and keys held back by the gate, need the next frame at once
    bool needsFrame = (app.script && !app.script->waitsForBackground()) || keyGate.holding();
    // work whose end the window must show without waiting for input
    bool background = !host.idle() || app.polynomial.job.running() || app.polynomial.check.pending() ||
                      app.picks.readout.pending() || app.picks.click.pending();
    keyGate.beginFrame(app.window);
    if (needsFrame) {
        glfwPollEvents();
    } else if (background) {
        glfwWaitEventsTimeout(std::max(0.0, app.frameStart + kBackgroundFrameSeconds - glfwGetTime()));
    } else if (app.script) {
        glfwPollEvents();  // the script's wait ends this frame
    } else {
        glfwWaitEventsTimeout(0.25);  // idle: no need to spin
    }
    // the frame's own time: what the window takes to answer, not its wait for input
    double start = glfwGetTime();
    app.frameStart = start;
    if (glfwWindowShouldClose(app.window)) {
        glfwSetWindowShouldClose(app.window, GLFW_FALSE);
        request(app, {PendingAction::Kind::Quit, {}});
    }
    if (app.script) {
        ui::ScriptStatus status = app.script->step(app.editor, app.ui, host);
        if (status == ui::ScriptStatus::Failed) {
            std::cerr << "sdf-workbench gui: " << app.script->error() << "\n";
            app.ui.error(app.script->error());
            app.exitCode = 1;
            app.quit = true;
        } else if (status == ui::ScriptStatus::Finished) {
            app.script.reset();
        }
    }

    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    handleShortcuts(app);
    app.imageThumbnails->update(*app.ui.imageCheck);
    drawMainWindow(app);
    app.viewport->update(app.editor.scene(), app.editor.revision(), app.ui, app.view.width, app.view.height,
                         app.view.interacting, app.view.interacting ? 0.020 : 0.025);
    app.thumbnails->update(app.view.interacting || app.ui.draggingNode);
    app.snapshot.poll();
    for (std::string outcome : {app.snapshot.takeOutcome(), app.meshExport.takeOutcome()}) {
        // "wrote ...", "... cancelled; nothing written" or "... failed: ...": only a failure is a problem
        if (!outcome.empty())
            (outcome.find(" failed: ") == std::string::npos ? app.ui.info(outcome) : app.ui.error(outcome));
    }
    autosaveTick(app, start);
    noteViewportError(app);
    for (const std::string& error : takeGlDebugErrors()) app.ui.error("GL: " + error);
    if (app.scripted) printNewMessages(app);
    // only on a change: setting it sends the window a property event, which
    // ended every wait for input at once and kept an idle window drawing
    if (std::string title = windowTitle(app); title != app.windowTitleShown) {
        glfwSetWindowTitle(app.window, title.c_str());
        app.windowTitleShown = std::move(title);
    }
    ImGui::Render();

    const glcontext::GlFunctions& gl = app.context->gl();
    int width = 0, height = 0;
    glfwGetFramebufferSize(app.window, &width, &height);
    gl.Viewport(0, 0, width, height);
    gl.ClearColor(0.1f, 0.1f, 0.11f, 1.0f);
    gl.Clear(GL_COLOR_BUFFER_BIT);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    if (app.screenshot) {
        try {
            captureWindow(gl, width, height, *app.screenshot);
            app.ui.info("screenshot " + app.screenshot->string());
        } catch (const std::exception& error) {
            std::cerr << "sdf-workbench gui: " << error.what() << "\n";
            app.ui.error(error.what());
            app.exitCode = 1;
            app.quit = true;
        }
        app.screenshot.reset();
    }
    glfwSwapBuffers(app.window);
    app.frameSeconds = static_cast<float>(glfwGetTime() - start);
    // the slowest frame of a 5-second window: shows whether the UI ever stalled
    if (start - app.slowestFrameSince > 5.0) {
        app.slowestFrameSince = start;
        app.slowestFrameSeconds = 0;
    }
    app.slowestFrameSeconds = std::max(app.slowestFrameSeconds, app.frameSeconds);
}

}  // namespace

int runGui(const GuiArguments& arguments) {
    // Everything that can fail without a window is checked first.
    scene::Scene scene;
    std::optional<ui::ScriptRunner> script;
    try {
        scene = loadSceneArgument(arguments.scene);
        // a file opened from the command line is a recent file like one opened
        // in the window (scripted runs leave the user's list alone)
        bool scripted = !arguments.script.empty() || !arguments.screenshot.empty();
        if (!scripted && std::filesystem::is_regular_file(arguments.scene)) RecentFiles().remember(arguments.scene);
        if (!arguments.script.empty()) {
            script.emplace(ui::parseScript(io::readTextFile(arguments.script), arguments.script), arguments.script);
        } else if (!arguments.screenshot.empty()) {
            image::checkWritableFormat(arguments.screenshot);
            checkOutputs({{"the scene", arguments.scene}}, {{"--screenshot", arguments.screenshot}});
            script.emplace(
                ui::parseScript(ui::screenshotScript(arguments.screenshot, arguments.frames), "--screenshot"),
                "--screenshot");
        }
    } catch (const scene::SceneError& error) {
        for (const std::string& problem : error.problems()) std::cerr << "sdf-workbench gui: " << problem << "\n";
        return kExitError;
    } catch (const std::exception& error) {
        std::cerr << "sdf-workbench gui: " << error.what() << "\n";
        return kExitError;
    }

    glfwSetErrorCallback([](int, const char* text) { glfwErrorText = text; });
    if (!glfwInit()) {
        std::cerr << "sdf-workbench gui: cannot open a window: " << glfwErrorText << "\n";
        return kNoWindow;
    }
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_SCALE_TO_MONITOR, GLFW_TRUE);
    // No larger than the screen's work area: on an 800x600 screen the 1280x800
    // window put the status bar and the restore dialog's buttons off the
    // screen. Scripts keep the size their screenshots are compared at.
    int width = arguments.width, height = arguments.height;
    if (GLFWmonitor* monitor = glfwGetPrimaryMonitor(); monitor && !script) {
        int x = 0, y = 0, areaWidth = 0, areaHeight = 0;
        glfwGetMonitorWorkarea(monitor, &x, &y, &areaWidth, &areaHeight);
        if (areaWidth > 0 && areaHeight > 0) {
            width = std::min(width, areaWidth);
            height = std::min(height, areaHeight);
        }
    }
    GLFWwindow* window = glfwCreateWindow(width, height, "SDF Workbench", nullptr, nullptr);
    if (!window) {
        std::cerr << "sdf-workbench gui: cannot open an OpenGL 3.3 window: " << glfwErrorText << "\n";
        glfwTerminate();
        return kNoWindow;
    }
    glfwMakeContextCurrent(window);
    glfwSwapInterval(script ? 0 : 1);

    int exitCode = 0;
    {
        IMGUI_CHECKVERSION();
        ImGui::CreateContext();
        ImGui::GetIO().IniFilename = nullptr;  // the layout is fixed; write nothing to the working directory
        float scaleX = 1, scaleY = 1;
        glfwGetWindowContentScale(window, &scaleX, &scaleY);
        setUpStyle(std::max(1.0f, scaleY));
        ImGui_ImplGlfw_InitForOpenGL(window, true);
        keyGate.setNext(glfwSetKeyCallback(window, onKey), glfwSetCharCallback(window, onChar));
        ImGui_ImplOpenGL3_Init("#version 330 core");

        AppState app;
        app.window = window;
        glfwSetWindowUserPointer(window, &app);
        try {
            app.context = GlfwContext::forWindow(window);
            app.viewport = std::make_unique<Viewport>(*app.context);
            app.thumbnails = std::make_unique<Thumbnails>(app.context->gl());
            app.imageThumbnails = std::make_unique<ImageThumbnails>(app.context->gl());
            app.ui.imageThumbnail = [&app](const std::string& key) { return app.imageThumbnails->lookup(key); };
            app.ui.listFolder = listFolder;
        } catch (const std::exception& error) {
            std::cerr << "sdf-workbench gui: " << error.what() << "\n";
            return 1;
        }
        app.editor.reset(std::move(scene));
        if (!arguments.scene.empty() && arguments.scene != "default") app.files.current = arguments.scene;
        app.script = std::move(script);
        app.scripted = app.script.has_value();
        app.files.offerRestore = !app.scripted && std::filesystem::exists(autosavePath());
        Host host(app);
        while (!app.quit) runFrame(app, host);
        glfwSetWindowUserPointer(window, nullptr);
        if (!app.scripted) removeAutosave();
        exitCode = app.exitCode;
        app.viewport.reset();
        app.thumbnails.reset();
        app.ui.imageThumbnail = nullptr;
        app.imageThumbnails.reset();
        ImGui_ImplOpenGL3_Shutdown();
        ImGui_ImplGlfw_Shutdown();
        ImGui::DestroyContext();
    }
    glfwDestroyWindow(window);
    glfwTerminate();
    return exitCode;
}

}  // namespace sdfwb::app::gui
