#include "app/gui/view_selection.h"

#include <cmath>

#include <glm/geometric.hpp>

#include "app/gui/app_state.h"
#include "app/gui/viewport_panel.h"
#include "ui/transform_handles.h"
#include "ui/view_picking.h"

namespace sdfwb::app::gui {
namespace {

constexpr float kClickSlop = 3.0f;  // pixels a click may move and still not be a drag
constexpr ImU32 kOutline = IM_COL32(255, 190, 60, 255);

constexpr ImU32 kAxisColours[] = {IM_COL32(235, 70, 70, 255), IM_COL32(110, 210, 80, 255), IM_COL32(80, 140, 245, 255)};
constexpr ImU32 kActiveHandle = IM_COL32(255, 230, 90, 255);

// The screen point of an image pixel.
ImVec2 screenPoint(const AppState& app, ImVec2 corner, ImVec2 size, glm::dvec2 p) {
    return ImVec2(corner.x + static_cast<float>(p.x) / static_cast<float>(app.view.width) * size.x,
                  corner.y + static_cast<float>(p.y) / static_cast<float>(app.view.height) * size.y);
}

// The selection's handles; the one being dragged, or else under the mouse, highlighted.
void handles(const AppState& app, ImVec2 corner, ImVec2 size) {
    if (!app.editor.selection()) return;
    ui::HandleMode mode = app.ui.handles;
    std::optional<ui::HandleLayout> layout =
        ui::handleLayout(app.editor.scene(), *app.editor.selection(), mode, app.view.width, app.view.height);
    if (!layout) return;
    std::optional<int> lit;
    if (app.handleDrag.active()) {
        lit = app.handleDrag.axis();
    } else if (ImGui::IsItemHovered() && !ImGui::IsItemActive()) {
        ImVec2 mouse = imagePixel(app, corner, size, ImGui::GetIO().MousePos);
        lit = ui::handleAt(*layout, mode, glm::dvec2(mouse.x, mouse.y));
    }
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->PushClipRect(corner, ImVec2(corner.x + size.x, corner.y + size.y), true);
    ImVec2 pivot = screenPoint(app, corner, size, layout->pivot);
    for (int axis = 0; axis < 3; ++axis) {
        if (!layout->visible[axis]) continue;
        ImU32 colour = lit == axis ? kActiveHandle : kAxisColours[axis];
        if (mode == ui::HandleMode::Rotate) {
            ImVec2 ring[ui::HandleLayout::kRingPoints];
            for (int i = 0; i < ui::HandleLayout::kRingPoints; ++i) ring[i] = screenPoint(app, corner, size, layout->ring[axis][i]);
            draw->AddPolyline(ring, ui::HandleLayout::kRingPoints, colour, ImDrawFlags_Closed, lit == axis ? 3.5f : 2.0f);
            continue;
        }
        ImVec2 tip = screenPoint(app, corner, size, layout->tip[axis]);
        draw->AddLine(pivot, tip, IM_COL32(0, 0, 0, 120), 5.0f);
        draw->AddLine(pivot, tip, colour, lit == axis ? 3.5f : 2.5f);
        if (mode == ui::HandleMode::Scale) {
            draw->AddRectFilled(ImVec2(tip.x - 5, tip.y - 5), ImVec2(tip.x + 5, tip.y + 5), colour);
        } else {
            glm::dvec2 along = glm::normalize(layout->tip[axis] - layout->pivot) * 10.0, across(-along.y * 0.5, along.x * 0.5);
            auto at = [&](glm::dvec2 d) { return ImVec2(tip.x + static_cast<float>(d.x), tip.y + static_cast<float>(d.y)); };
            draw->AddTriangleFilled(at(along), at(across), at(-across), colour);
        }
    }
    draw->AddCircleFilled(pivot, 4.0f, IM_COL32(240, 240, 240, 230));
    draw->PopClipRect();
}

void outline(const AppState& app, ImVec2 corner, ImVec2 size) {
    if (!app.editor.selection()) return;
    std::optional<ui::ImageRect> rect =
        ui::outlineRect(app.editor.scene(), *app.editor.selection(), app.view.width, app.view.height);
    if (!rect) return;
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->PushClipRect(corner, ImVec2(corner.x + size.x, corner.y + size.y), true);
    ImVec2 a = screenPoint(app, corner, size, rect->min), b = screenPoint(app, corner, size, rect->max);
    draw->AddRect(ImVec2(a.x - 3, a.y - 3), ImVec2(b.x + 3, b.y + 3), IM_COL32(0, 0, 0, 140), 0, 0, 4.0f);
    draw->AddRect(ImVec2(a.x - 3, a.y - 3), ImVec2(b.x + 3, b.y + 3), kOutline, 0, 0, 2.0f);
    draw->PopClipRect();
}

// Asks for the pixel under the cursor and shows the newest reading: dimmed
// while it is of another scene state or view size than the one drawn.
void readout(AppState& app, ImVec2 corner, ImVec2 size) {
    ImVec2 pixel = imagePixel(app, corner, size, ImGui::GetIO().MousePos);
    app.picks.readout.request(app.editor.scene(), app.editor.revision(), app.view.width, app.view.height, pixel.x,
                              pixel.y);
    std::optional<ui::PixelReading> reading = app.picks.readout.latest();
    if (!reading) return;
    bool current = reading->revision == app.editor.revision() && reading->width == app.view.width &&
                   reading->height == app.view.height;
    std::string text = ui::readoutText(reading->pick);
    ImDrawList* draw = ImGui::GetWindowDrawList();
    // above the image's note, which it covered half of
    const float note = app.viewport->main().note.empty() ? 0 : slotNoteHeight();
    ImVec2 at(corner.x + 8, corner.y + size.y - note - ImGui::GetTextLineHeight() - 8);
    ImVec2 extent = ImGui::CalcTextSize(text.c_str());
    draw->AddRectFilled(ImVec2(at.x - 4, at.y - 3), ImVec2(at.x + extent.x + 4, at.y + extent.y + 3),
                        IM_COL32(20, 22, 26, 190), 3);
    draw->AddText(at, current ? IM_COL32(230, 232, 236, 255) : IM_COL32(150, 152, 156, 255), text.c_str());
}

// A click's pick selects once ready, unless the scene changed meanwhile.
void applyClick(AppState& app) {
    if (!app.picks.clickPending || app.picks.click.pending()) return;
    app.picks.clickPending = false;
    std::optional<ui::PixelReading> reading = app.picks.click.latest();
    if (!reading || reading->revision != app.editor.revision()) return;
    ui::selectPicked(app.editor, reading->pick);
    app.ui.showTab = ui::InspectorTab::Node;
}

}  // namespace

ImVec2 imagePixel(const AppState& app, ImVec2 corner, ImVec2 size, ImVec2 screen) {
    return ImVec2((screen.x - corner.x) / size.x * static_cast<float>(app.view.width),
                  (screen.y - corner.y) / size.y * static_cast<float>(app.view.height));
}

void viewSelection(AppState& app, ImVec2 corner, ImVec2 size) {
    if (app.view.width <= 0 || app.view.height <= 0) return;
    if (ImGui::IsItemDeactivated() && ImGui::IsMouseReleased(ImGuiMouseButton_Left) && !app.pressTookHandle) {
        ImVec2 drag = ImGui::GetMouseDragDelta(ImGuiMouseButton_Left, 0.0f);
        if (std::hypot(drag.x, drag.y) < kClickSlop) {
            ImVec2 pixel = imagePixel(app, corner, size, ImGui::GetIO().MousePos);
            app.picks.click.request(app.editor.scene(), app.editor.revision(), app.view.width, app.view.height,
                                    pixel.x, pixel.y);
            app.picks.clickPending = true;
        }
    }
    applyClick(app);
    outline(app, corner, size);
    handles(app, corner, size);
    if (app.ui.pixelReadout && ImGui::IsItemHovered() && !ImGui::IsItemActive()) readout(app, corner, size);
}

}  // namespace sdfwb::app::gui
