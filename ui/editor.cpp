#include "ui/editor.h"

#include "scene/scene_json.h"

namespace sdfwb::ui {

using scene::Node;
using scene::NodeKind;
using json = nlohmann::ordered_json;

Editor::Editor(scene::Scene scene) : scene_(std::move(scene)) {}

void Editor::select(std::optional<NodePath> path) {
    if (path && !findNode(scene_.root, *path)) {
        path.reset();
    }
    selection_ = std::move(path);
}

const Node* Editor::selectedNode() const { return selection_ ? findNode(scene_.root, *selection_) : nullptr; }

Problems Editor::commit(std::string_view label, scene::Scene candidate, std::optional<NodePath> selection,
                        std::string_view mergeKey) {
    Problems problems = scene::validateScene(candidate, &formulaVerdicts_);
    if (!problems.empty()) {
        return problems;
    }
    bool merge = mergeOpen_ && !mergeKey.empty() && !undo_.empty() && undo_.back().mergeKey == mergeKey;
    if (!merge) {
        undo_.push_back({std::move(scene_), selection_, std::string(label), std::string(mergeKey), stateId_});
    }
    redo_.clear();
    mergeOpen_ = !mergeKey.empty();
    scene_ = std::move(candidate);
    stateId_ = nextStateId_++;
    ++revision_;
    select(std::move(selection));
    return {};
}

Problems Editor::apply(std::string_view label, const std::function<void(scene::Scene&)>& change,
                       std::string_view mergeKey) {
    scene::Scene candidate = scene_;
    change(candidate);
    return commit(label, std::move(candidate), selection_, mergeKey);
}

namespace {

Problems noNode(const NodePath& path) { return {formatNodePath(path) + ": no such node"}; }

bool takesAnotherChild(const Node& node) {
    const scene::KindSpec& spec = scene::kindSpec(node.kind);
    return spec.maxChildren < 0 || static_cast<int>(node.children.size()) < spec.maxChildren;
}

}  // namespace

Problems Editor::setField(const NodePath& path, std::string_view field, scene::FieldValue value,
                          std::string_view mergeKey) {
    const Node* node = findNode(scene_.root, path);
    if (!node) {
        return noNode(path);
    }
    const scene::KindSpec& spec = scene::kindSpec(node->kind);
    if (scene::fieldIndex(spec, field) < 0) {
        std::string list = "name";
        for (const scene::FieldSpec& f : spec.fields) {
            list += ", " + std::string(f.name);
        }
        return {formatNodePath(path) + "." + std::string(field) + ": unknown field (" + std::string(spec.name) +
                " has: " + list + ")"};
    }
    scene::Scene candidate = scene_;
    findNode(candidate.root, path)->set(field, std::move(value));
    return commit("Set " + std::string(field), std::move(candidate), selection_, mergeKey);
}

Problems Editor::rename(const NodePath& path, std::string name) {
    if (!findNode(scene_.root, path)) {
        return noNode(path);
    }
    scene::Scene candidate = scene_;
    findNode(candidate.root, path)->name = std::move(name);
    return commit("Rename", std::move(candidate), selection_, {});
}

Problems Editor::setHidden(const NodePath& path, bool hidden) {
    if (!findNode(scene_.root, path)) return noNode(path);
    scene::Scene candidate = scene_;
    findNode(candidate.root, path)->hidden = hidden;
    return commit(hidden ? "Hide" : "Show", std::move(candidate), selection_, {});
}

Problems Editor::setSolo(const NodePath& path, bool solo) {
    if (!findNode(scene_.root, path)) return noNode(path);
    scene::Scene candidate = scene_;
    findNode(candidate.root, path)->solo = solo;
    return commit(solo ? "Solo" : "End solo", std::move(candidate), selection_, {});
}

Problems Editor::insert(const NodePath& parent, int index, Node node, std::string_view label) {
    const Node* target = findNode(scene_.root, parent);
    if (!target) {
        return noNode(parent);
    }
    if (!takesAnotherChild(*target)) {
        return {formatNodePath(parent) + ": a " + std::string(scene::kindSpec(target->kind).name) +
                " node takes no more children"};
    }
    int count = static_cast<int>(target->children.size());
    if (index < 0 || index > count) {
        index = count;
    }
    std::string name = label.empty() ? "Add " + std::string(scene::kindSpec(node.kind).name) : std::string(label);
    scene::Scene candidate = scene_;
    auto& children = findNode(candidate.root, parent)->children;
    children.insert(children.begin() + index, std::move(node));
    NodePath added = parent;
    added.push_back(index);
    return commit(name, std::move(candidate), added, {});
}

Problems Editor::add(NodeKind kind, const std::optional<NodePath>& under) {
    if (scene::kindSpec(kind).minChildren > 0) {
        // an operator that needs a child cannot stand alone: it wraps the target
        return wrap(under.value_or(selection_.value_or(NodePath{})), kind);
    }
    return add(Node::make(kind), under);
}

std::optional<std::pair<NodePath, int>> Editor::insertionPoint(const std::optional<NodePath>& under) const {
    NodePath target = under.value_or(selection_.value_or(NodePath{}));
    const Node* existing = findNode(scene_.root, target);
    if (!existing) {
        return std::nullopt;
    }
    if (takesAnotherChild(*existing)) {
        return std::pair{target, -1};
    }
    if (!target.empty() && takesAnotherChild(*findNode(scene_.root, parentOf(target)))) {
        return std::pair{parentOf(target), target.back() + 1};
    }
    return std::pair{NodePath{}, -1};
}

Problems Editor::add(Node node, const std::optional<NodePath>& under) {
    std::optional<std::pair<NodePath, int>> where = insertionPoint(under);
    if (!where) {
        return noNode(under.value_or(selection_.value_or(NodePath{})));
    }
    return insert(where->first, where->second, std::move(node));
}

Problems Editor::wrap(const NodePath& path, NodeKind kind) {
    const Node* node = findNode(scene_.root, path);
    if (!node) {
        return noNode(path);
    }
    if (scene::kindSpec(kind).maxChildren == 0) {
        return {"cannot wrap in a " + std::string(scene::kindSpec(kind).name) + ": it takes no children"};
    }
    scene::Scene candidate = scene_;
    Node* slot = findNode(candidate.root, path);
    Node wrapper = Node::make(kind);
    wrapper.children.push_back(std::move(*slot));
    *slot = std::move(wrapper);
    return commit("Wrap in " + std::string(scene::kindSpec(kind).name), std::move(candidate), path, {});
}

Problems Editor::move(const NodePath& from, const NodePath& newParent, int index) {
    if (from.empty()) {
        return {"root: the root node cannot be moved"};
    }
    if (!findNode(scene_.root, from)) {
        return noNode(from);
    }
    if (!findNode(scene_.root, newParent)) {
        return noNode(newParent);
    }
    if (isWithin(newParent, from)) {
        return {formatNodePath(from) + ": cannot move a node into itself"};
    }
    NodePath oldParent = parentOf(from);
    // Where the new parent and index are once the node has left its old place.
    NodePath target = newParent;
    if (isWithin(newParent, oldParent) && newParent.size() > oldParent.size() &&
        newParent[oldParent.size()] > from.back()) {
        --target[oldParent.size()];
    }
    if (newParent == oldParent && index > from.back()) {
        --index;
    }
    scene::Scene candidate = scene_;
    auto& oldChildren = findNode(candidate.root, oldParent)->children;
    Node moving = std::move(oldChildren[static_cast<size_t>(from.back())]);
    oldChildren.erase(oldChildren.begin() + from.back());
    Node* parent = findNode(candidate.root, target);
    if (!takesAnotherChild(*parent)) {
        return {formatNodePath(newParent) + ": a " + std::string(scene::kindSpec(parent->kind).name) +
                " node takes no more children"};
    }
    int count = static_cast<int>(parent->children.size());
    if (index < 0 || index > count) {
        index = count;
    }
    parent->children.insert(parent->children.begin() + index, std::move(moving));
    NodePath moved = target;
    moved.push_back(index);
    return commit("Move", std::move(candidate), moved, {});
}

Problems Editor::duplicate(const NodePath& path) {
    if (path.empty()) {
        return {"root: the root node cannot be duplicated (wrap it in an operation first)"};
    }
    const Node* node = findNode(scene_.root, path);
    if (!node) {
        return noNode(path);
    }
    return insert(parentOf(path), path.back() + 1, *node);
}

Problems Editor::remove(const NodePath& path) {
    if (path.empty()) {
        return {"root: the root node cannot be deleted"};
    }
    const Node* node = findNode(scene_.root, path);
    if (!node) {
        return noNode(path);
    }
    std::string label = "Delete " + std::string(scene::kindSpec(node->kind).name);
    // a wrapper that needs a child (translate, twist, ...) goes with the node
    // it held, and so on up: what is left is always a valid scene
    NodePath removed = path;
    while (removed.size() > 1) {
        const Node* parent = findNode(scene_.root, parentOf(removed));
        if (scene::kindSpec(parent->kind).minChildren < static_cast<int>(parent->children.size())) break;
        removed = parentOf(removed);
    }
    scene::Scene candidate = scene_;
    NodePath parent = parentOf(removed);
    Node& holder = *findNode(candidate.root, parent);
    holder.children.erase(holder.children.begin() + removed.back());
    if (holder.children.size() < static_cast<size_t>(scene::kindSpec(holder.kind).minChildren)) {
        holder = Node::make(NodeKind::Union);  // the root wrapper itself left empty
    }
    size_t wrappers = path.size() - removed.size();
    if (wrappers > 0) label += " and " + std::to_string(wrappers) + (wrappers == 1 ? " wrapper" : " wrappers");
    return commit(label, std::move(candidate), parent, {});
}

Problems Editor::setJsonValue(std::string_view jsonPath, const json& value, std::string_view mergeKey) {
    std::vector<JsonStep> steps;
    if (!splitJsonPath(jsonPath, steps)) {
        return {std::string(jsonPath) + ": not a JSON path (write e.g. render.aa or lights[0].softness)"};
    }
    json document = scene::sceneToJson(scene_);
    json* at = &document;
    std::string walked;
    for (size_t i = 0; i < steps.size(); ++i) {
        const JsonStep& step = steps[i];
        bool last = i + 1 == steps.size();
        if (step.key.empty()) {
            if (!at->is_array() || static_cast<size_t>(step.index) >= at->size()) {
                return {walked + "[" + std::to_string(step.index) + "]: no such element" +
                        (at->is_array() ? " (" + walked + " has " + std::to_string(at->size()) + ")" : "")};
            }
            at = &(*at)[static_cast<size_t>(step.index)];
            walked += "[" + std::to_string(step.index) + "]";
        } else {
            walked += (walked.empty() ? "" : ".") + step.key;
            if (!at->is_object() || (!last && !at->contains(step.key))) {
                return {walked + ": no such field"};
            }
            at = &(*at)[step.key];  // a new key on the last step is reported by the loader
        }
    }
    *at = value;
    scene::Scene candidate;
    try {
        candidate = scene::sceneFromJson(document);
    } catch (const scene::SceneError& error) {
        return error.problems();
    }
    candidate.directory = scene_.directory;  // not in the document: image names stay relative to the same folder
    return commit("Set " + walked, std::move(candidate), selection_, mergeKey);
}

std::string_view Editor::undoLabel() const { return undo_.empty() ? std::string_view() : undo_.back().label; }
std::string_view Editor::redoLabel() const { return redo_.empty() ? std::string_view() : redo_.back().label; }

Problems Editor::setView(const scene::Camera& camera) {
    if (Problems problems = scene::cameraProblems(camera); !problems.empty()) return problems;
    if (scene_.camera != camera) {
        scene_.camera = camera;
        ++revision_;
    }
    return {};
}

void Editor::setDirectory(std::string directory) {
    if (scene_.directory.path != directory) {
        scene_.directory.path = std::move(directory);
        ++revision_;
    }
}

void Editor::restore(Step& from, std::vector<Step>& to) {
    scene::Camera view = scene_.camera;
    scene::SceneDirectory directory = scene_.directory;
    to.push_back({std::move(scene_), selection_, from.label, {}, stateId_});
    scene_ = std::move(from.scene);
    scene_.camera = view;
    scene_.directory = std::move(directory);
    stateId_ = from.stateId;
    ++revision_;
    mergeOpen_ = false;
    select(from.selection);
}

bool Editor::undo() {
    if (undo_.empty()) return false;
    Step step = std::move(undo_.back());
    undo_.pop_back();
    restore(step, redo_);
    return true;
}

bool Editor::redo() {
    if (redo_.empty()) return false;
    Step step = std::move(redo_.back());
    redo_.pop_back();
    restore(step, undo_);
    return true;
}

void Editor::reset(scene::Scene scene) {
    scene_ = std::move(scene);
    selection_.reset();
    undo_.clear();
    redo_.clear();
    mergeOpen_ = false;
    stateId_ = nextStateId_++;
    savedStateId_ = stateId_;
    ++revision_;
}

}  // namespace sdfwb::ui
