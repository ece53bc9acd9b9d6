#include "ui/problems.h"

#include <algorithm>

#include "scene/scene_json.h"

namespace sdfwb::ui {
namespace {

using json = nlohmann::ordered_json;

constexpr size_t kKeptMessages = 200;  // the oldest go first

// The scene file's top-level keys a cause can start with, and the tab that edits each.
struct TopKey {
    std::string_view key;
    InspectorTab tab;
};
constexpr TopKey kTopKeys[] = {
    {"root", InspectorTab::Node},           {"render", InspectorTab::Render},
    {"environment", InspectorTab::Environment}, {"camera", InspectorTab::Render},
    {"lights", InspectorTab::Lights},       {"materials", InspectorTab::Materials},
};

const json* walk(const json& document, const std::vector<JsonStep>& steps, size_t first) {
    const json* at = &document;
    for (size_t i = first; i < steps.size(); ++i) {
        const JsonStep& step = steps[i];
        if (step.key.empty()) {
            if (!at->is_array() || static_cast<size_t>(step.index) >= at->size()) return nullptr;
            at = &(*at)[static_cast<size_t>(step.index)];
        } else {
            if (!at->is_object() || !at->contains(step.key)) return nullptr;
            at = &(*at)[step.key];
        }
    }
    return at;
}

}  // namespace

std::optional<ProblemCause> problemCause(std::string_view message) {
    size_t colon = message.find(": ");
    if (colon == std::string_view::npos) return std::nullopt;
    std::string_view path = message.substr(0, colon);
    std::vector<JsonStep> steps;
    if (!splitJsonPath(path, steps) || steps.front().key.empty()) return std::nullopt;
    auto top = std::find_if(std::begin(kTopKeys), std::end(kTopKeys),
                            [&](const TopKey& k) { return k.key == steps.front().key; });
    if (top == std::end(kTopKeys)) return std::nullopt;
    ProblemCause cause{std::string(path), std::nullopt, top->tab};
    if (top->key == "root") {
        NodePath node;
        for (size_t i = 1; i + 1 < steps.size() && steps[i].key == "children" && steps[i + 1].key.empty(); i += 2) {
            node.push_back(steps[i + 1].index);
        }
        cause.node = node;
    }
    return cause;
}

json valueAt(const scene::Scene& scene, const ProblemCause& cause) {
    std::vector<JsonStep> steps;
    if (!splitJsonPath(cause.jsonPath, steps)) return nullptr;
    if (cause.node) {
        const scene::Node* node = findNode(scene.root, *cause.node);
        if (!node) return nullptr;
        // the node's own fields, not its subtree: a cause deep in a big tree stays cheap
        scene::Node alone = *node;
        alone.children.clear();
        const json document = scene::nodeToJson(alone);
        const json* at = walk(document, steps, 1 + 2 * cause.node->size());
        return at ? *at : json();
    }
    scene::Scene settings;  // everything but the tree
    settings.camera = scene.camera;
    settings.render = scene.render;
    settings.environment = scene.environment;
    settings.lights = scene.lights;
    settings.materials = scene.materials;
    const json document = scene::sceneToJson(settings);
    const json* at = walk(document, steps, 0);
    return at ? *at : json();
}

void updateProblems(UiState& ui, const Editor& editor) {
    if (ui.messages.size() > kKeptMessages) {
        ui.messages.erase(ui.messages.begin(), ui.messages.end() - static_cast<long>(kKeptMessages));
    }
    for (size_t i = 0; i < ui.messages.size(); ++i) {
        Message& m = ui.messages[i];
        if (m.watched) continue;
        m.watched = true;
        m.revision = editor.revision();
        if (m.level != Message::Level::Error) continue;
        std::optional<ProblemCause> cause = problemCause(m.text);
        if (!cause) continue;
        m.causeValue = valueAt(editor.scene(), *cause).dump();
        for (size_t j = 0; j < i; ++j) {  // a newer error of the same cause replaces the older
            Message& older = ui.messages[j];
            std::optional<ProblemCause> olderCause = problemCause(older.text);
            if (older.level == Message::Level::Error && olderCause && olderCause->jsonPath == cause->jsonPath) {
                older.resolved = true;
            }
        }
    }
    if (ui.problemsCheckedAt == editor.revision()) return;
    ui.problemsCheckedAt = editor.revision();
    for (Message& m : ui.messages) {
        if (m.resolved || m.level != Message::Level::Error || m.revision == editor.revision()) continue;
        std::optional<ProblemCause> cause = problemCause(m.text);
        if (cause && valueAt(editor.scene(), *cause).dump() != m.causeValue) m.resolved = true;
    }
}

void goToCause(Editor& editor, UiState& ui, const ProblemCause& cause) {
    if (cause.node) editor.select(*cause.node);
    ui.showTab = cause.tab;
}

std::vector<const Message*> openErrors(const UiState& ui) {
    std::vector<const Message*> out;
    for (auto m = ui.messages.rbegin(); m != ui.messages.rend(); ++m) {
        if (m->level == Message::Level::Error && !m->resolved) out.push_back(&*m);
    }
    return out;
}

}  // namespace sdfwb::ui
