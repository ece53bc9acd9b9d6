#include "app/gui/key_gate.h"

#include <algorithm>
#include <utility>

#include <GLFW/glfw3.h>

namespace sdfwb::app::gui {

void KeyGate::onKey(GLFWwindow* window, int key, int scancode, int action, int mods) {
    // once one event waits, all later ones wait behind it, in order: a Ctrl
    // released right after Ctrl+A must stay down while ImGui sees the A
    bool waiting = !held_.empty();
    bool wentDown = std::find(downThisFrame_.begin(), downThisFrame_.end(), key) != downThisFrame_.end();
    if (waiting || (action == GLFW_RELEASE && wentDown)) {
        held_.push_back({key, scancode, action, mods});
        return;
    }
    if (action == GLFW_PRESS) downThisFrame_.push_back(key);
    if (next_) next_(window, key, scancode, action, mods);
}

void KeyGate::beginFrame(GLFWwindow* window) {
    downThisFrame_.clear();
    // a quick double tap holds press and release again, one frame each
    for (const Event& e : std::exchange(held_, {})) onKey(window, e.key, e.scancode, e.action, e.mods);
}

}  // namespace sdfwb::app::gui
