// The scene tree: one row per node (kind, name, thumbnail), selection,
// context menu (add, wrap, duplicate, delete, rename), and drag and drop:
// dropping on a row's upper or lower edge puts the node before or after it,
// on its middle into it.

#include <imgui.h>
#include <imgui_stdlib.h>

#include "ui/formula_field.h"
#include "ui/panels.h"
#include "ui/placement.h"

namespace sdfwb::ui {
namespace {

constexpr const char* kDragType = "SDFWB_NODE";
constexpr float kThumbnailSize = 26.0f;

struct TreeContext {
    Editor& editor;
    UiState& ui;
    const ThumbnailLookup& thumbnails;
    // Applied after the tree is drawn, so the tree never changes mid-walk.
    std::function<void()> pending;
};

std::string rowLabel(const scene::Node& node) {
    std::string label(scene::kindSpec(node.kind).name);
    if (!node.name.empty()) label += "  \"" + node.name + "\"";
    return label;
}

void dropTarget(TreeContext& tree, const NodePath& path, const scene::Node& node) {
    if (!ImGui::BeginDragDropTarget()) return;
    // where in the row the mouse is: top quarter before, bottom quarter after, else into
    ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
    float t = (ImGui::GetMousePos().y - min.y) / (max.y - min.y);
    bool into = path.empty() || (scene::kindSpec(node.kind).maxChildren != 0 && t > 0.25f && t < 0.75f);
    bool after = t >= 0.5f;
    const ImGuiDragDropFlags flags = ImGuiDragDropFlags_AcceptBeforeDelivery | ImGuiDragDropFlags_AcceptNoDrawDefaultRect;
    if (const ImGuiPayload* payload = ImGui::AcceptDragDropPayload(kDragType, flags)) {
        ImDrawList* draw = ImGui::GetWindowDrawList();
        const ImU32 colour = ImGui::GetColorU32(ImGuiCol_DragDropTarget);
        if (into) {
            draw->AddRect(min, max, colour, 0.0f, 0, 2.0f);
        } else {
            float y = after ? max.y : min.y;
            draw->AddLine(ImVec2(min.x, y), ImVec2(max.x, y), colour, 3.0f);
        }
        if (payload->IsDelivery()) {
            auto* data = static_cast<const int*>(payload->Data);
            NodePath from(data, data + payload->DataSize / static_cast<int>(sizeof(int)));
            if (into) {
                tree.pending = [&tree, from, path] { reportProblems(tree.ui, tree.editor.move(from, path, -1)); };
            } else {
                int index = path.back() + (after ? 1 : 0);
                NodePath parent = parentOf(path);
                tree.pending = [&tree, from, parent, index] {
                    reportProblems(tree.ui, tree.editor.move(from, parent, index));
                };
            }
        }
    }
    ImGui::EndDragDropTarget();
}

void contextMenu(TreeContext& tree, const NodePath& path) {
    if (!ImGui::BeginPopupContextItem()) return;
    tree.editor.select(path);
    if (ImGui::BeginMenu("Add")) {
        drawAddMenuItems(tree.editor, tree.ui);
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Wrap in")) {
        drawWrapMenuItems(tree.editor, tree.ui);
        ImGui::EndMenu();
    }
    if (ImGui::MenuItem("Duplicate", "Ctrl+D", false, !path.empty())) {
        tree.pending = [&tree, path] { reportProblems(tree.ui, duplicatePlaced(tree.editor, path)); };
    }
    if (ImGui::MenuItem("Delete", "Del", false, !path.empty())) {
        tree.pending = [&tree, path] { reportProblems(tree.ui, tree.editor.remove(path)); };
    }
    ImGui::Separator();
    const scene::Node* node = findNode(tree.editor.scene().root, path);
    std::string name = node ? node->name : "";
    ImGui::SetNextItemWidth(160);
    if (ImGui::InputTextWithHint("##rename", "name", &name, ImGuiInputTextFlags_EnterReturnsTrue)) {
        tree.pending = [&tree, path, name] { reportProblems(tree.ui, tree.editor.rename(path, name)); };
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
}

// A toggle at the row's right end, lit when on.
bool rowToggle(const char* label, bool on, const char* tip) {
    ImGui::PushStyleColor(ImGuiCol_Button, on ? IM_COL32(200, 140, 40, 255) : IM_COL32(60, 64, 72, 160));
    bool pressed = ImGui::SmallButton(label);
    ImGui::PopStyleColor();
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tip);
    return pressed;
}

// Hide (H) and solo (S) of the row's node at the right end of the row. Drawn
// before the row, so they take the mouse before the row does; the cursor goes
// back to the row's start.
void visibilityToggles(TreeContext& tree, const scene::Node& node, const NodePath& path) {
    ImVec2 row = ImGui::GetCursorScreenPos();
    float right = row.x + ImGui::GetContentRegionAvail().x;
    float width = ImGui::CalcTextSize("H").x + 2 * ImGui::GetStyle().FramePadding.x;
    float rowHeight = tree.thumbnails ? kThumbnailSize : ImGui::GetFrameHeight();
    ImGui::SetCursorScreenPos(ImVec2(right - 2 * width - 4, row.y + 0.5f * (rowHeight - ImGui::GetTextLineHeight())));
    if (rowToggle("H", node.hidden, node.hidden ? "Hidden: draws nothing (click to show)" : "Hide: draw nothing, as if deleted, until shown again")) {
        tree.pending = [&tree, path, hidden = !node.hidden] { reportProblems(tree.ui, tree.editor.setHidden(path, hidden)); };
    }
    ImGui::SameLine(0, 2);
    if (rowToggle("S", node.solo, node.solo ? "Solo: only soloed nodes draw (click to end)" : "Solo: draw only this node (and other soloed ones)")) {
        tree.pending = [&tree, path, solo = !node.solo] { reportProblems(tree.ui, tree.editor.setSolo(path, solo)); };
    }
    ImGui::SetCursorScreenPos(row);
}

void drawNode(TreeContext& tree, const scene::Node& node, NodePath& path) {
    ImGui::PushID(static_cast<int>(path.empty() ? -1 : path.back()));
    visibilityToggles(tree, node, path);
    if (tree.thumbnails) {
        ImTextureID texture = tree.thumbnails(path, node);
        if (texture) {
            ImGui::Image(texture, ImVec2(kThumbnailSize, kThumbnailSize));
        } else {
            ImGui::Dummy(ImVec2(kThumbnailSize, kThumbnailSize));
        }
        ImGui::SameLine();
    }
    ImGuiTreeNodeFlags flags = ImGuiTreeNodeFlags_OpenOnArrow | ImGuiTreeNodeFlags_DefaultOpen |
                               ImGuiTreeNodeFlags_SpanAvailWidth | ImGuiTreeNodeFlags_FramePadding |
                               ImGuiTreeNodeFlags_AllowItemOverlap;
    if (node.children.empty()) flags |= ImGuiTreeNodeFlags_Leaf;
    if (tree.editor.selection() == path) flags |= ImGuiTreeNodeFlags_Selected;
    if (tree.thumbnails) {
        ImGui::PushStyleVar(ImGuiStyleVar_FramePadding, ImVec2(4, (kThumbnailSize - ImGui::GetTextLineHeight()) / 2));
    }
    if (node.hidden) ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    bool open = ImGui::TreeNodeEx("node", flags, "%s", rowLabel(node).c_str());
    if (node.hidden) ImGui::PopStyleColor();
    if (tree.thumbnails) ImGui::PopStyleVar();
    if (ImGui::IsItemClicked() && !ImGui::IsItemToggledOpen()) {
        tree.editor.select(path);
        tree.ui.inspectorProblems.clear();
        tree.ui.showTab = InspectorTab::Node;  // what was selected is what the user wants to see
    }
    if (!path.empty() && ImGui::BeginDragDropSource()) {
        ImGui::SetDragDropPayload(kDragType, path.data(), path.size() * sizeof(int));
        ImGui::Text("move %s", rowLabel(node).c_str());
        tree.ui.draggingNode = true;
        ImGui::EndDragDropSource();
    }
    dropTarget(tree, path, node);
    contextMenu(tree, path);
    if (open) {
        for (size_t i = 0; i < node.children.size(); ++i) {
            path.push_back(static_cast<int>(i));
            drawNode(tree, node.children[i], path);
            path.pop_back();
        }
        ImGui::TreePop();
    }
    ImGui::PopID();
}

}  // namespace

void drawSceneTree(Editor& editor, UiState& ui, const ThumbnailLookup& thumbnails) {
    TreeContext tree{editor, ui, thumbnails, {}};
    ui.draggingNode = false;
    NodePath path;
    drawNode(tree, editor.scene().root, path);
    if (tree.pending) tree.pending();
}

void drawAddMenuItems(Editor& editor, UiState& ui) {
    // primitives first, then the operations that take any number of children;
    // unary operators are in the Wrap menu
    for (bool primitives : {true, false}) {
        ImGui::TextDisabled(primitives ? "Primitives" : "Operations");
        for (const scene::KindSpec& spec : scene::allKinds()) {
            bool isPrimitive = spec.category == scene::NodeCategory::Primitive;
            if (isPrimitive != primitives || spec.minChildren > 0) continue;
            if (formulaField(spec)) {
                drawAddFormulaMenu(editor, ui, spec);
            } else if (ImGui::MenuItem(std::string(spec.name).c_str())) {
                reportProblems(ui, addPlaced(editor, spec.kind));
            }
        }
        if (primitives) ImGui::Separator();
    }
}

void drawWrapMenuItems(Editor& editor, UiState& ui) {
    bool enabled = editor.selection().has_value();
    for (const scene::KindSpec& spec : scene::allKinds()) {
        if (spec.maxChildren == 0) continue;
        if (ImGui::MenuItem(std::string(spec.name).c_str(), nullptr, false, enabled)) {
            reportProblems(ui, editor.wrap(*editor.selection(), spec.kind));
        }
    }
}

}  // namespace sdfwb::ui
