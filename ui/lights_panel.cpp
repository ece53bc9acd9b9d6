// Lights: up to scene::kMaxLights directional lights, one widget per row of
// the light settings table (the direction also as azimuth and elevation
// angles and as a gizmo).

#include <algorithm>
#include <cmath>

#include <glm/vec2.hpp>

#include <imgui.h>

#include "ui/panel_widgets.h"
#include "ui/panels.h"
#include "ui/setting_widgets.h"

namespace sdfwb::ui {
namespace {

// A light added to a lit scene: a soft fill from the other side at a third of
// white, so the scene is not blown out (the scene format's default light is a
// full-strength key light).
scene::Light newLight() {
    scene::Light light;
    light.direction = glm::dvec3(-0.5, 0.6, -0.4);
    light.color = glm::dvec3(0.35);
    light.softness = 6.0;
    return light;
}

constexpr double kDegrees = 180.0 / 3.14159265358979323846;

// Azimuth about +y from +z towards +x, elevation above the horizon, degrees.
glm::dvec2 anglesOf(const glm::dvec3& d) {
    double length = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
    return {std::atan2(d.x, d.z) * kDegrees, std::asin(std::clamp(d.y / length, -1.0, 1.0)) * kDegrees};
}
glm::dvec3 directionOf(double azimuth, double elevation) {
    double a = azimuth / kDegrees, e = elevation / kDegrees;
    return {std::cos(e) * std::sin(a), std::sin(e), std::cos(e) * std::cos(a)};
}

// A top view of the sky: the light's direction projected on the ground
// plane (centre: straight overhead, rim: the horizon). Dragging aims it.
WidgetEdit directionGizmo(glm::dvec3& direction) {
    const float radius = 34.0f;
    ImGui::TextDisabled("top view,\ndrag to aim");
    ImGui::SameLine(110);
    ImVec2 corner = ImGui::GetCursorScreenPos();
    ImVec2 centre(corner.x + radius, corner.y + radius);
    ImGui::InvisibleButton("gizmo", ImVec2(2 * radius, 2 * radius));
    bool changed = false;
    if (ImGui::IsItemActive()) {
        ImVec2 mouse = ImGui::GetIO().MousePos;
        double x = (mouse.x - centre.x) / radius, z = (mouse.y - centre.y) / radius;
        double r = std::sqrt(x * x + z * z);
        if (r > 0.995) {
            x *= 0.995 / r;
            z *= 0.995 / r;
        }
        direction = {x, std::sqrt(std::max(0.0, 1.0 - x * x - z * z)), z};
        changed = true;
    }
    WidgetEdit edit{changed, ImGui::IsItemDeactivated()};
    double length = std::sqrt(direction.x * direction.x + direction.y * direction.y + direction.z * direction.z);
    ImVec2 point(centre.x + static_cast<float>(direction.x / length) * radius,
                 centre.y + static_cast<float>(direction.z / length) * radius);
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->AddCircleFilled(centre, radius, IM_COL32(40, 48, 60, 255));
    draw->AddCircle(centre, radius, IM_COL32(120, 130, 150, 255));
    draw->AddLine(centre, point, IM_COL32(255, 220, 120, 255), 2.0f);
    draw->AddCircleFilled(point, 4.0f, direction.y >= 0 ? IM_COL32(255, 220, 120, 255) : IM_COL32(140, 120, 80, 255));
    return edit;  // the button is the last item: commitEdit keys the drag by its id
}

}  // namespace

void drawLightsPanel(Editor& editor, UiState& ui) {
    const size_t count = editor.scene().lights.size();
    ImGui::BeginDisabled(count >= static_cast<size_t>(scene::kMaxLights));
    if (ImGui::Button("Add light")) {
        reportProblems(ui, editor.apply("Add light", [](scene::Scene& s) { s.lights.push_back(newLight()); }));
    }
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::TextDisabled("%zu of %d", count, scene::kMaxLights);
    for (size_t i = 0; i < editor.scene().lights.size(); ++i) {
        scene::Light light = editor.scene().lights[i];
        ImGui::PushID(static_cast<int>(i));
        std::string title = "Light " + std::to_string(i + 1);
        if (ImGui::CollapsingHeader(title.c_str(), ImGuiTreeNodeFlags_DefaultOpen)) {
            auto set = [&, i](WidgetEdit edit) {
                commitEdit(editor, ui, edit, "Edit light", [&light, i](scene::Scene& s) { s.lights[i] = light; });
            };
            for (const scene::Setting<scene::Light>& row : scene::lightSettings()) {
                const bool direction = row.type == scene::SettingType::Direction;
                if (direction) {  // the same vector as two angles, then as a vector, then as a gizmo
                    glm::dvec2 angles = anglesOf(light.direction);
                    double angle[2] = {angles.x, angles.y};
                    bool changed = ImGui::DragScalarN("az / el (deg)", ImGuiDataType_Double, angle, 2, 0.5f, nullptr,
                                                      nullptr, "%.1f");
                    if (changed) light.direction = directionOf(angle[0], std::clamp(angle[1], -89.9, 89.9));
                    set({changed, ImGui::IsItemDeactivatedAfterEdit()});
                }
                set(settingWidget(row, light));
                if (direction) set(directionGizmo(light.direction));
            }
            if (ImGui::SmallButton("Remove")) {
                reportProblems(ui, editor.apply("Remove light", [i](scene::Scene& s) {
                    s.lights.erase(s.lights.begin() + static_cast<long>(i));
                }));
            }
        }
        ImGui::PopID();
    }
}

}  // namespace sdfwb::ui
