// Lights: up to scene::kMaxLights directional lights, each with its direction
// as azimuth and elevation angles (or the raw vector), colour and softness k.

#include <algorithm>
#include <cmath>

#include <glm/vec2.hpp>

#include <imgui.h>

#include "ui/panel_widgets.h"
#include "ui/panels.h"

namespace sdfwb::ui {
namespace {

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

}  // namespace

void drawLightsPanel(Editor& editor, UiState& ui) {
    const size_t count = editor.scene().lights.size();
    ImGui::BeginDisabled(count >= static_cast<size_t>(scene::kMaxLights));
    if (ImGui::Button("Add light")) {
        reportProblems(ui, editor.apply("Add light", [](scene::Scene& s) { s.lights.push_back({}); }));
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
            glm::dvec2 angles = anglesOf(light.direction);
            double angle[2] = {angles.x, angles.y};
            bool changed = ImGui::DragScalarN("azimuth, elevation", ImGuiDataType_Double, angle, 2, 0.5f);
            if (changed) light.direction = directionOf(angle[0], std::clamp(angle[1], -89.9, 89.9));
            set({changed, ImGui::IsItemDeactivatedAfterEdit()});
            set(dragVec3("direction", light.direction, 0.01, -1e6, 1e6));
            set(colorEdit("colour", light.color));
            set(dragReal("softness k", light.softness, 0.05, 0.01, 1000.0, "%.2f"));
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
