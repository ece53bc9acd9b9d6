// The inspector: the selected node's name and fields, with a widget per field
// type chosen from the node-kind table, and its material.

#include <limits>

#include <imgui.h>
#include <imgui_stdlib.h>

#include "ui/field_help.h"
#include "ui/formula_field.h"
#include "ui/panel_widgets.h"
#include "ui/panels.h"

namespace sdfwb::ui {
namespace {

using scene::FieldSpec;
using scene::FieldType;
using scene::Range;

constexpr double kHuge = std::numeric_limits<double>::max();

// Drag speed and limits that suit a field: angles move by half degrees,
// sizes never go below zero through the drag (typed values are validated).
struct DragRange {
    double speed, minimum, maximum;
};
DragRange dragRangeFor(const FieldSpec& field) {
    bool angle = field.unit == "degrees";
    double speed = angle ? 0.5 : 0.01;
    switch (field.range) {
    case Range::Positive: return {speed, 1e-4, kHuge};
    case Range::NonNegative: return {speed, 0.0, kHuge};
    case Range::NonNegativeInteger: return {0.05, 0.0, 1e6};
    case Range::Integer2or3: return {0.05, 2.0, 3.0};
    case Range::OpenAngle90: return {0.25, 0.5, 89.5};
    case Range::Any:
    case Range::NonZeroVector: return {speed, -kHuge, kHuge};
    case Range::SdfFormula:
    case Range::ImplicitFormula:
    case Range::PolynomialFormula: break;  // text fields: never dragged
    }
    return {speed, -kHuge, kHuge};
}

std::string fieldLabel(const FieldSpec& field) {
    std::string label(field.name);
    if (!field.unit.empty()) label += " (" + std::string(field.unit) + ")";
    return label;
}

void materialCombo(Editor& editor, UiState& ui, const NodePath& path, const FieldSpec& field,
                   const std::string& current) {
    const scene::Scene& scene = editor.scene();
    if (ImGui::BeginCombo("material", current.empty() ? "(default)" : current.c_str())) {
        if (ImGui::Selectable("(default)", current.empty())) {
            reportProblems(ui, editor.setField(path, field.name, std::string()));
        }
        for (const scene::Material& m : scene.materials) {
            if (ImGui::Selectable(m.name.c_str(), m.name == current)) {
                reportProblems(ui, editor.setField(path, field.name, m.name));
            }
        }
        ImGui::Separator();
        if (ImGui::Selectable("New material")) {
            std::string name;
            for (int i = 1; name.empty() || scene.findMaterial(name); ++i) name = "material " + std::to_string(i);
            Problems problems = editor.apply("New material", [&](scene::Scene& s) {
                scene::Material m;
                m.name = name;
                s.materials.push_back(m);
                findNode(s.root, path)->set(field.name, name);
            });
            reportProblems(ui, problems);
        }
        ImGui::EndCombo();
    }
}

void fieldWidget(Editor& editor, UiState& ui, const NodePath& path, const FieldSpec& field,
                 const scene::FieldValue& value) {
    std::string label = fieldLabel(field);
    auto setter = [&](scene::FieldValue v) {
        return [&path, &field, v](scene::Scene& s) { findNode(s.root, path)->set(field.name, v); };
    };
    switch (field.type) {
    case FieldType::Real: {
        double v = std::get<double>(value);
        DragRange r = dragRangeFor(field);
        const char* format = field.range == Range::Integer2or3 || field.range == Range::NonNegativeInteger ? "%.0f" : "%.3f";
        WidgetEdit edit = dragReal(label.c_str(), v, r.speed, r.minimum, r.maximum, format);
        commitEdit(editor, ui, edit, "Edit field", setter(v), formatNodePath(path) + "." + std::string(field.name));
        break;
    }
    case FieldType::Vec3: {
        glm::dvec3 v = std::get<glm::dvec3>(value);
        DragRange r = dragRangeFor(field);
        const char* format = field.range == Range::NonNegativeInteger ? "%.0f" : "%.3f";
        WidgetEdit edit = dragVec3(label.c_str(), v, r.speed, r.minimum, r.maximum, format);
        commitEdit(editor, ui, edit, "Edit field", setter(v), formatNodePath(path) + "." + std::string(field.name));
        break;
    }
    case FieldType::Choice: {
        const std::string& current = std::get<std::string>(value);
        if (ImGui::BeginCombo(label.c_str(), current.c_str())) {
            for (std::string_view choice : field.choices) {
                if (ImGui::Selectable(std::string(choice).c_str(), choice == current)) {
                    reportProblems(ui, editor.setField(path, field.name, std::string(choice)));
                }
            }
            ImGui::EndCombo();
        }
        break;
    }
    case FieldType::Material:
        materialCombo(editor, ui, path, field, std::get<std::string>(value));
        break;
    case FieldType::Formula:
        drawFormulaField(editor, ui, path, field, std::get<std::string>(value));
        break;
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", fieldTooltip(field).c_str());
}

// With no node selected: the scene's own name and description.
void drawSceneProperties(Editor& editor, UiState& ui) {
    ImGui::TextDisabled("Scene (select a node in the tree to edit it)");
    std::string name = editor.scene().name;
    if (ImGui::InputText("name", &name, ImGuiInputTextFlags_EnterReturnsTrue)) {
        reportProblems(ui, editor.apply("Rename scene", [&](scene::Scene& s) { s.name = name; }));
    }
    std::string description = editor.scene().description;
    ImGui::TextDisabled("description");
    if (ImGui::InputTextMultiline("##description", &description, ImVec2(-1, 120))) {
        reportProblems(ui, editor.apply("Edit description", [&](scene::Scene& s) { s.description = description; },
                                        "scene description"));
    }
    if (ImGui::IsItemDeactivated()) editor.endMerge();
}

}  // namespace

void drawInspector(Editor& editor, UiState& ui) {
    const scene::Node* node = editor.selectedNode();
    if (!node) {
        drawSceneProperties(editor, ui);
        return;
    }
    const NodePath path = *editor.selection();
    const scene::KindSpec& spec = scene::kindSpec(node->kind);
    ImGui::Text("%s", std::string(spec.name).c_str());
    ImGui::SameLine();
    ImGui::TextDisabled("%s  (%s)", formatNodePath(path).c_str(),
                        spec.quality == scene::DistanceQuality::Exact ? "exact" : "bound");
    std::string name = node->name;
    if (ImGui::InputText("name", &name, ImGuiInputTextFlags_EnterReturnsTrue)) {
        reportProblems(ui, editor.rename(path, name));
    }
    ImGui::PushItemWidth(-110);
    for (size_t i = 0; i < spec.fields.size(); ++i) {
        ImGui::PushID(static_cast<int>(i));
        // the node may have been replaced by an edit above: read it again
        const scene::Node* current = findNode(editor.scene().root, path);
        if (current) fieldWidget(editor, ui, path, spec.fields[i], current->fields[i]);
        ImGui::PopID();
    }
    ImGui::PopItemWidth();
    if (spec.maxChildren != 0) {
        bool folded = spec.category == scene::NodeCategory::Boolean;
        ImGui::TextDisabled("%zu child%s%s", node->children.size(), node->children.size() == 1 ? "" : "ren",
                            folded ? ", folded in child order (drag to reorder)" : "");
    }
    for (const std::string& problem : ui.inspectorProblems) problemText(problem);
}

}  // namespace sdfwb::ui
