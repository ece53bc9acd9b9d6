#pragma once
// The editor's widget for one row of a settings table (scene/settings_table.h):
// its label, range and drag hints come from the row, so a new setting needs no
// widget code of its own.

#include <type_traits>

#include <imgui.h>

#include "scene/settings_table.h"
#include "ui/panel_widgets.h"

namespace sdfwb::ui {

// `speed` overrides the row's drag speed when > 0.
template <typename Owner>
WidgetEdit settingWidget(const scene::Setting<Owner>& row, Owner& owner, double speed = 0) {
    using scene::SettingType;
    std::string label(row.label);
    double drag = speed > 0 ? speed : row.widget.speed;
    switch (row.type) {
    case SettingType::Integer: {
        int& value = owner.*std::get<int Owner::*>(row.member);
        bool changed = ImGui::DragInt(label.c_str(), &value, static_cast<float>(drag), static_cast<int>(row.minimum),
                                      static_cast<int>(row.maximum));
        return {changed, ImGui::IsItemDeactivatedAfterEdit()};
    }
    case SettingType::Real:
        return dragReal(label.c_str(), owner.*std::get<double Owner::*>(row.member), drag, row.widget.minimum,
                        row.widget.maximum, row.widget.format);
    case SettingType::Choice: {
        const scene::ChoiceMember<Owner>& access = std::get<scene::ChoiceMember<Owner>>(row.member);
        int index = access.get(owner);
        bool changed = ImGui::Combo(label.c_str(), &index, row.choices.data(), static_cast<int>(row.choices.size()));
        if (changed) access.set(owner, index);
        return {changed, changed};  // each choice is its own undo step
    }
    case SettingType::Colour: return colorEdit(label.c_str(), owner.*std::get<glm::dvec3 Owner::*>(row.member));
    case SettingType::Vector:
    case SettingType::Direction:
        return dragVec3(label.c_str(), owner.*std::get<glm::dvec3 Owner::*>(row.member), 0.01, -1e6, 1e6);
    case SettingType::Flag: {
        bool changed = ImGui::Checkbox(label.c_str(), &(owner.*std::get<bool Owner::*>(row.member)));
        return {changed, changed};
    }
    case SettingType::Text: break;  // names and references have their own widgets
    }
    return {};
}

}  // namespace sdfwb::ui
