#include "ui/node_path.h"

#include <charconv>

#include "scene/visibility.h"

namespace sdfwb::ui {

std::string formatNodePath(const NodePath& path) {
    std::string text = "root";
    for (int index : path) {
        text += ".children[" + std::to_string(index) + "]";
    }
    return text;
}

std::optional<NodePath> parseNodePath(std::string_view text) {
    constexpr std::string_view kRoot = "root", kStep = ".children[";
    if (!text.starts_with(kRoot)) {
        return std::nullopt;
    }
    text.remove_prefix(kRoot.size());
    NodePath path;
    while (!text.empty()) {
        if (!text.starts_with(kStep)) {
            return std::nullopt;
        }
        text.remove_prefix(kStep.size());
        int index = -1;
        auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), index);
        if (error != std::errc() || index < 0 || end == text.data() + text.size() || *end != ']') {
            return std::nullopt;
        }
        path.push_back(index);
        text.remove_prefix(static_cast<size_t>(end - text.data()) + 1);
    }
    return path;
}

bool splitJsonPath(std::string_view text, std::vector<JsonStep>& steps) {
    while (!text.empty()) {
        if (text.front() == '[') {
            size_t close = text.find(']');
            if (close == std::string_view::npos) return false;
            int index = -1;
            auto [end, error] = std::from_chars(text.data() + 1, text.data() + close, index);
            if (error != std::errc() || end != text.data() + close || index < 0) return false;
            steps.push_back({"", index});
            text.remove_prefix(close + 1);
        } else {
            if (text.front() == '.') {
                if (steps.empty()) return false;
                text.remove_prefix(1);
            }
            size_t end = text.find_first_of(".[");
            std::string_view key = text.substr(0, end);
            if (key.empty()) return false;
            steps.push_back({std::string(key), -1});
            text.remove_prefix(key.size());
        }
    }
    return !steps.empty();
}


namespace {
template <typename NodeT>
NodeT* walk(NodeT& root, const NodePath& path) {
    NodeT* node = &root;
    for (int index : path) {
        if (index < 0 || static_cast<size_t>(index) >= node->children.size()) {
            return nullptr;
        }
        node = &node->children[static_cast<size_t>(index)];
    }
    return node;
}
}  // namespace

const scene::Node* findNode(const scene::Node& root, const NodePath& path) { return walk(root, path); }
scene::Node* findNode(scene::Node& root, const NodePath& path) { return walk(root, path); }

bool drawsAt(const scene::Node& root, const NodePath& path) {
    const scene::Visibility visibility(root);
    const scene::Node* node = &root;
    if (!visibility.draws(*node)) return false;
    for (int index : path) {
        if (index < 0 || static_cast<size_t>(index) >= node->children.size()) return false;
        node = &node->children[static_cast<size_t>(index)];
        if (!visibility.draws(*node)) return false;
    }
    return true;
}

bool isWithin(const NodePath& inner, const NodePath& outer) {
    return inner.size() >= outer.size() && std::equal(outer.begin(), outer.end(), inner.begin());
}

NodePath parentOf(const NodePath& path) { return NodePath(path.begin(), path.end() - 1); }

}  // namespace sdfwb::ui
