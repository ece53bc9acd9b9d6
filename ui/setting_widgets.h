#pragma once
// The editor's widget for one row of a settings table (scene/settings_table.h):
// its label, range and drag hints come from the row, so a new setting needs no
// widget code of its own.

#include <cstdio>
#include <string>
#include <type_traits>

#include <imgui.h>

#include "scene/settings_table.h"
#include "ui/panel_widgets.h"

namespace sdfwb::ui {

// The widget alone (settingWidget adds the tooltip).
template <typename Owner>
WidgetEdit settingWidgetOnly(const scene::Setting<Owner>& row, Owner& owner, double speed) {
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
    case SettingType::Text:
    case SettingType::ImageFile: break;  // names, references and files have their own widgets
    }
    return {};
}

// What the row says about its value, for the widget's tooltip: the JSON key,
// unit and allowed values.
template <typename Owner>
std::string settingHint(const scene::Setting<Owner>& row) {
    using scene::RealRange;
    using scene::SettingType;
    auto number = [](double v) {
        char text[32];
        std::snprintf(text, sizeof text, "%g", v);
        return std::string(text);
    };
    std::string hint = "JSON key " + std::string(row.key);
    if (!row.unit.empty()) hint += ", in " + std::string(row.unit);
    std::string allowed;
    switch (row.type) {
    case SettingType::Integer: allowed = "whole numbers from " + number(row.minimum) + " to " + number(row.maximum); break;
    case SettingType::Real:
        switch (row.range) {
        case RealRange::Any: allowed = "any finite number"; break;
        case RealRange::Positive: allowed = "> 0"; break;
        case RealRange::NonNegative: allowed = ">= 0"; break;
        case RealRange::Closed: allowed = "from " + number(row.minimum) + " to " + number(row.maximum); break;
        case RealRange::Open: allowed = "between " + number(row.minimum) + " and " + number(row.maximum) + ", ends excluded"; break;
        }
        break;
    case SettingType::Choice:
        for (const char* choice : row.choices) allowed += (allowed.empty() ? "" : ", ") + std::string(choice);
        break;
    case SettingType::Colour: allowed = "linear RGB, each >= 0 (above 1 is brighter than white)"; break;
    case SettingType::Direction: allowed = "any vector but zero (normalised when rendered)"; break;
    case SettingType::Vector:
    case SettingType::Flag:
    case SettingType::Text: break;
    case SettingType::ImageFile:
        allowed = "an image file (PNG, JPEG, TIFF, EXR), relative to the scene file's folder";
        break;
    }
    if (!allowed.empty()) hint += "\nallowed: " + allowed;
    if (row.type == SettingType::Integer || row.type == SettingType::Real) hint += "\nCtrl+click or double-click to type a value";
    return hint;
}

// `speed` overrides the row's drag speed when > 0.
template <typename Owner>
WidgetEdit settingWidget(const scene::Setting<Owner>& row, Owner& owner, double speed = 0) {
    WidgetEdit edit = settingWidgetOnly(row, owner, speed);
    if (ImGui::IsItemHovered() && !ImGui::IsItemActive()) ImGui::SetTooltip("%s", settingHint(row).c_str());
    return edit;
}

}  // namespace sdfwb::ui
