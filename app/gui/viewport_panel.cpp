#include "app/gui/viewport_panel.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <string>

#include <imgui.h>

#include <glm/vec2.hpp>

#include "app/gui/view_selection.h"
#include "image/encoding.h"
#include "image/image.h"
#include "ui/view_camera.h"

namespace sdfwb::app::gui {
namespace {

// Orbit with the left button, pan the target with the right or middle
// button, distance with the wheel: view changes, not undo steps (ui/view_camera.h).
// A left press on a handle of the selection drags the handle instead (Ctrl
// snaps), one undo step per drag.
bool cameraControls(AppState& app, ImVec2 corner, ImVec2 size) {
    ImGui::InvisibleButton("camera", size,
                           ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight |
                               ImGuiButtonFlags_MouseButtonMiddle);
    const ImGuiIO& io = ImGui::GetIO();
    bool active = ImGui::IsItemActive();
    ImVec2 pixel = imagePixel(app, corner, size, io.MousePos);
    if (ImGui::IsItemActivated()) {
        app.pressTookHandle = ImGui::IsMouseClicked(ImGuiMouseButton_Left) && app.ui.compare == ui::CompareMode::Off &&
                              app.handleDrag.begin(app.editor, app.ui.handles, app.view.width, app.view.height,
                                                   glm::dvec2(pixel.x, pixel.y));
    }
    if (app.handleDrag.active()) {
        if (!active) {
            app.handleDrag.end(app.editor);
        } else {  // every frame, so pressing or letting go of Ctrl snaps at once
            ui::Problems problems = app.handleDrag.update(app.editor, glm::dvec2(pixel.x, pixel.y), io.KeyCtrl);
            if (!problems.empty()) app.ui.error(problems.front());
        }
        return active;
    }
    const scene::Scene& s = app.editor.scene();
    if (active && (io.MouseDelta.x != 0 || io.MouseDelta.y != 0)) {
        ImVec2 d = io.MouseDelta;
        bool pan = ImGui::IsMouseDown(ImGuiMouseButton_Right) || ImGui::IsMouseDown(ImGuiMouseButton_Middle);
        app.editor.setView(pan ? ui::panned(s.camera, d.x, d.y, size.y)
                               : ui::orbited(s.camera, s.environment, -0.4 * d.x, 0.4 * d.y));
    }
    if (ImGui::IsItemHovered() && io.MouseWheel != 0) {
        app.editor.setView(ui::zoomed(s.camera, s.environment, io.MouseWheel));
    }
    return active;
}

// Why the view shows nothing, and the way back.
void viewHint(const AppState& app, ImVec2 corner, ImVec2 size) {
    const scene::Scene& s = app.editor.scene();
    const char* hint = nullptr;
    if (ui::eyeBelowGround(s.camera, s.environment)) {
        hint = "The camera is below the ground. Press Home (Frame all) or drag down to come back up.";
    } else if (app.viewport->stats().frame.hitRatio == 0 && app.viewport->stats().width > 0) {
        hint = "Nothing in view. Press Home (Frame all) to see the whole scene.";
    }
    if (!hint) return;
    ImVec2 text = ImGui::CalcTextSize(hint);
    ImVec2 at(corner.x + std::max(8.0f, 0.5f * (size.x - text.x)), corner.y + size.y - text.y - 40);
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->AddRectFilled(ImVec2(at.x - 8, at.y - 6), ImVec2(at.x + text.x + 8, at.y + text.y + 6), IM_COL32(20, 22, 26, 200), 4);
    draw->AddText(at, IM_COL32(255, 220, 120, 255), hint);
}

void toolbar(AppState& app) {
    ui::UiState& ui = app.ui;
    if (ImGui::RadioButton("GLSL", ui.backend == ui::ViewBackend::Gl)) ui.backend = ui::ViewBackend::Gl;
    ImGui::SameLine();
    if (ImGui::RadioButton("CPU", ui.backend == ui::ViewBackend::Cpu)) ui.backend = ui::ViewBackend::Cpu;
    ImGui::SameLine(0, 14);
    ImGui::SetNextItemWidth(120);
    const char* modes[] = {"no compare", "side by side", "difference"};
    int mode = static_cast<int>(ui.compare);
    if (ImGui::Combo("##compare", &mode, modes, 3)) ui.compare = static_cast<ui::CompareMode>(mode);
    ImGui::SameLine(0, 14);
    ImGui::Checkbox("step heat", &ui.stepHeat);
    ImGui::SameLine();
    ImGui::Checkbox("stats", &ui.showStats);
    ImGui::SameLine(0, 14);
    static constexpr const char* kModes[] = {"Move", "Rotate", "Scale"};
    static constexpr const char* kTips[] = {"Drag an arrow of the selection to move it along that axis (G); Ctrl snaps to 0.1",
                                            "Drag a ring of the selection to turn it about that axis (R); Ctrl snaps to 15 degrees",
                                            "Drag a handle of the selection to scale it, uniformly (S); Ctrl snaps to 0.1 of its size"};
    for (int i = 0; i < 3; ++i) {
        if (i > 0) ImGui::SameLine();
        if (ImGui::RadioButton(kModes[i], ui.handles == static_cast<ui::HandleMode>(i))) ui.handles = static_cast<ui::HandleMode>(i);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", kTips[i]);
    }
    ImGui::SameLine(0, 14);
    if (ImGui::Button("Frame all")) frameAll(app);
    ImGui::SameLine();
    if (ImGui::Button("Snapshot...")) app.snapshot.dialogOpen = true;
}

std::string formatted(const char* format, auto... values) {
    char line[256];
    std::snprintf(line, sizeof line, format, values...);
    return line;
}

// A child of the viewport window, so it stays above the image however focus
// moves; sized to its lines as they are measured, so none is cut off.
void statsOverlay(AppState& app, ImVec2 corner) {
    const Viewport& viewport = *app.viewport;
    const ViewportStats& s = viewport.stats();
    // the compare views show both images, and these figures are the GLSL side's
    bool comparing = app.ui.compare != ui::CompareMode::Off;
    const char* backend = comparing ? "GLSL figures, CPU compared" : app.ui.backend == ui::ViewBackend::Gl ? "GLSL" : "CPU";
    const std::string lines[] = {
        formatted("frame %.0f ms (slowest %.0f)   backend %s", app.frameSeconds * 1000.0f,
                  app.slowestFrameSeconds * 1000.0f, backend),
        formatted("image %d x %d, AA %d, %.0f ms (GPU %.0f ms)", s.width, s.height, s.aa, s.renderSeconds * 1000.0,
                  s.gpuSeconds * 1000.0),
        formatted("steps/pixel mean %.1f, max %.0f, hits %.0f%%", s.frame.meanSteps, s.frame.maxSteps,
                  s.frame.hitRatio * 100.0),
        formatted("field evaluations/pixel mean %.1f (march, normals, material, AO, shadows)", s.frame.meanEvaluations),
        "GL " + viewport.glInfo().renderer,
        formatted("shaders built %d, last %.2f s", s.compiles, s.compileSeconds),
        s.status,
    };
    const ImGuiStyle& style = ImGui::GetStyle();
    float widest = 0;
    for (const std::string& line : lines) widest = std::max(widest, ImGui::CalcTextSize(line.c_str()).x);
    const float count = static_cast<float>(std::size(lines));
    ImVec2 size(widest + 2 * style.WindowPadding.x,
                count * ImGui::GetTextLineHeightWithSpacing() + 2 * style.WindowPadding.y - style.ItemSpacing.y);
    ImGui::SetCursorScreenPos(ImVec2(corner.x + 8, corner.y + 8));
    ImGui::PushStyleColor(ImGuiCol_ChildBg, IM_COL32(20, 22, 26, 160));
    ImGui::BeginChild("stats", size, false,
                      ImGuiWindowFlags_NoInputs | ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_AlwaysUseWindowPadding);
    for (const std::string& line : lines) ImGui::TextUnformatted(line.c_str());
    ImGui::EndChild();
    ImGui::PopStyleColor();
}

}  // namespace

float slotNoteHeight() { return ImGui::GetTextLineHeightWithSpacing() + 8; }

namespace {

// One slot's image with its caption at the bottom left and, when the image
// is not the current state's (view_choice.h), its note on a dark band along
// the bottom, above which the caption moves.
void slotImage(const SlotImage& slot, ImVec2 corner, ImVec2 size, const char* caption) {
    ImGui::Image(slot.texture->id(), size);
    ImDrawList* draw = ImGui::GetWindowDrawList();
    float bottom = corner.y + size.y;
    if (!slot.note.empty()) {
        const float band = slotNoteHeight();
        draw->PushClipRect(corner, ImVec2(corner.x + size.x, bottom), true);
        draw->AddRectFilled(ImVec2(corner.x, bottom - band), ImVec2(corner.x + size.x, bottom),
                            IM_COL32(20, 22, 26, 200));
        draw->AddText(ImVec2(corner.x + 8, bottom - band + 4), IM_COL32(255, 210, 120, 255), slot.note.c_str());
        draw->PopClipRect();
        bottom -= band;
    }
    if (*caption) draw->AddText(ImVec2(corner.x + 8, bottom - 22), IM_COL32_WHITE, caption);
}

// The heat view's key: the ramp from 0 steps to the scene's max steps, at the right edge.
void heatLegend(const AppState& app, ImVec2 corner, ImVec2 size) {
    constexpr int kBands = 32;
    const float barWidth = 14, barHeight = std::min(220.0f, size.y - 80);
    if (barHeight < 40) return;
    ImVec2 top(corner.x + size.x - barWidth - 56, corner.y + 30);
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->AddRectFilled(ImVec2(top.x - 6, top.y - 22), ImVec2(corner.x + size.x - 6, top.y + barHeight + 8),
                        IM_COL32(20, 22, 26, 190), 4);
    auto colour = [](float t) {
        image::LinearRgb c = image::heatRamp(t);
        return IM_COL32(image::encodeSrgb8(c.r), image::encodeSrgb8(c.g), image::encodeSrgb8(c.b), 255);
    };
    for (int i = 0; i < kBands; ++i) {  // many steps at the top
        float t0 = 1.0f - static_cast<float>(i) / kBands, t1 = 1.0f - static_cast<float>(i + 1) / kBands;
        float y0 = top.y + barHeight * static_cast<float>(i) / kBands, y1 = top.y + barHeight * static_cast<float>(i + 1) / kBands;
        draw->AddRectFilledMultiColor(ImVec2(top.x, y0), ImVec2(top.x + barWidth, y1), colour(t0), colour(t0), colour(t1), colour(t1));
    }
    const int maxSteps = app.editor.scene().render.maxSteps;
    draw->AddText(ImVec2(top.x, top.y - 18), IM_COL32(230, 232, 236, 255), "steps");
    for (int k = 0; k <= 2; ++k) {
        std::string label = std::to_string(maxSteps * (2 - k) / 2);
        float y = top.y + barHeight * static_cast<float>(k) / 2 - ImGui::GetTextLineHeight() / 2;
        draw->AddText(ImVec2(top.x + barWidth + 6, y), IM_COL32(230, 232, 236, 255), label.c_str());
    }
}

void comparisonLine(const AppState& app) {
    const auto& c = app.viewport->comparison();
    if (!c) {
        ImGui::TextDisabled("comparing: waiting for both backends...");
        return;
    }
    bool pass = image::passes(*c, image::kParityThresholds);
    ImGui::TextColored(pass ? ImVec4(0.5f, 0.9f, 0.5f, 1) : ImVec4(1, 0.45f, 0.4f, 1),
                       "%s: max %.0f/255, mean %.3f/255, PSNR %.1f dB, pixels >1/255 %.3f%%, >8/255 %.3f%%",
                       pass ? "backends agree" : "backends differ", c->maxAbs, c->meanAbs, c->psnr,
                       c->percentAbove1, c->percentAbove8);
}

}  // namespace

void frameAll(AppState& app) {
    app.editor.setView(ui::frameAllCamera(app.editor.scene()));
}

void drawViewportPanel(AppState& app) {
    toolbar(app);
    if (app.ui.compare != ui::CompareMode::Off) comparisonLine(app);
    if (!app.viewport->error().empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, IM_COL32(255, 110, 100, 255));
        ImGui::TextWrapped("%s", app.viewport->errorLine().c_str());
        ImGui::PopStyleColor();
    }
    ImVec2 corner = ImGui::GetCursorScreenPos();
    ImVec2 size = ImGui::GetContentRegionAvail();
    size.x = std::max(size.x, 16.0f);
    size.y = std::max(size.y, 16.0f);
    const ImVec2 scale = ImGui::GetIO().DisplayFramebufferScale;
    app.view.width = static_cast<int>(size.x * scale.x);
    app.view.height = static_cast<int>(size.y * scale.y);

    const Viewport& viewport = *app.viewport;
    switch (app.ui.compare) {
    case ui::CompareMode::Off:
        slotImage(viewport.main(), corner, size, "");
        break;
    case ui::CompareMode::SideBySide: {
        ImVec2 half(size.x / 2, size.y);
        slotImage(viewport.main(), corner, half, "GLSL");
        ImGui::SameLine(0, 0);
        slotImage(viewport.second(), ImVec2(corner.x + half.x, corner.y), half, "CPU");
        break;
    }
    case ui::CompareMode::Difference:
        slotImage(viewport.difference(), corner, size,
                  "|GLSL - CPU| per pixel: black equal, blue small, yellow, red 8/255 or more");
        break;
    }
    ImGui::SetCursorScreenPos(corner);
    bool dragging = cameraControls(app, corner, size);
    if (app.ui.compare == ui::CompareMode::Off) viewSelection(app, corner, size);
    viewHint(app, corner, size);
    if (app.ui.stepHeat && app.ui.compare == ui::CompareMode::Off) heatLegend(app, corner, size);
    // A slider drag counts as interaction while it keeps changing the scene
    // (not, say, while a tree row is dragged): render the quick preview then.
    double now = ImGui::GetTime();
    if (app.editor.revision() != app.lastRevision) {
        app.lastRevision = app.editor.revision();
        app.lastChange = now;
    }
    bool editing = ImGui::IsAnyItemActive() && ImGui::IsMouseDown(ImGuiMouseButton_Left) && now - app.lastChange < 0.5;
    app.view.interacting = dragging || editing;
    if (app.ui.showStats) statsOverlay(app, corner);
}

}  // namespace sdfwb::app::gui
