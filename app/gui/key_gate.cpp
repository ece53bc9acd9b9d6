#include "app/gui/key_gate.h"

#include <algorithm>
#include <utility>

#include <GLFW/glfw3.h>

namespace sdfwb::app::gui {
namespace {

// Enter, Backspace, arrows, Home, keypad keys...: the keys that act on text.
// Printable keys (below 256) only come with their character; modifiers
// (from GLFW_KEY_LEFT_SHIFT on) change no text themselves.
bool isEditingKey(int key) { return key >= GLFW_KEY_ESCAPE && key < GLFW_KEY_LEFT_SHIFT; }

}  // namespace

void KeyGate::setNext(KeyCallback key, CharCallback character) {
    nextKey_ = key;
    nextChar_ = character;
}

void KeyGate::onKey(GLFWwindow* window, int key, int scancode, int action, int mods) {
    deliver(window, {false, key, scancode, action, mods, 0});
}

void KeyGate::onChar(GLFWwindow* window, unsigned int codepoint) { deliver(window, {true, 0, 0, 0, 0, codepoint}); }

void KeyGate::deliver(GLFWwindow* window, const Event& event) {
    // once one event waits, all later ones wait behind it, in order: a Ctrl
    // released right after Ctrl+A must stay down while ImGui sees the A
    bool changesKey = !event.isChar && event.action != GLFW_REPEAT;
    bool changedAlready = changesKey && std::find(changedThisFrame_.begin(), changedThisFrame_.end(), event.key) !=
                                            changedThisFrame_.end();
    // ImGui 1.86 inserts a frame's characters before it acts on its keys, so a
    // character typed after an editing key (Backspace, then "c") waits a frame
    bool charAfterKey = event.isChar && std::any_of(changedThisFrame_.begin(), changedThisFrame_.end(), isEditingKey);
    if (!held_.empty() || changedAlready || charAfterKey) {
        held_.push_back(event);
        return;
    }
    if (event.isChar) {
        if (nextChar_) nextChar_(window, event.codepoint);
        return;
    }
    if (changesKey) changedThisFrame_.push_back(event.key);
    if (nextKey_) nextKey_(window, event.key, event.scancode, event.action, event.mods);
}

void KeyGate::beginFrame(GLFWwindow* window) {
    changedThisFrame_.clear();
    // a quick double tap waits again: each change of a key gets its own frame
    for (const Event& e : std::exchange(held_, {})) deliver(window, e);
}

}  // namespace sdfwb::app::gui
