#include "scene/visibility.h"

#include <vector>

namespace sdfwb::scene {

Visibility::Visibility(const Node& root) {
    // one walk with an explicit stack (trees nest kMaxNodeDepth deep); the
    // path from the root is kept so that a soloed node marks its ancestors
    struct Pending {
        const Node* node;
        size_t nextChild;
        bool inSolo;
    };
    std::vector<Pending> stack{{&root, 0, root.solo}};
    if (root.solo) shownBySolo_.insert(&root);
    anySolo_ = root.solo;
    while (!stack.empty()) {
        Pending& top = stack.back();
        if (top.nextChild == top.node->children.size()) {
            stack.pop_back();
            continue;
        }
        const Node* child = &top.node->children[top.nextChild++];
        bool inSolo = top.inSolo || child->solo;
        if (child->solo && !top.inSolo) {
            anySolo_ = true;
            for (const Pending& above : stack) shownBySolo_.insert(above.node);
        }
        if (inSolo) shownBySolo_.insert(child);
        stack.push_back({child, 0, inSolo});
    }
}

bool Visibility::draws(const Node& node) const {
    return !node.hidden && (!anySolo_ || shownBySolo_.contains(&node));
}

}  // namespace sdfwb::scene
