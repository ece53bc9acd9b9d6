#pragma once
// ImGui 1.86 samples the keyboard once a frame (io.KeysDown), so a key pressed
// and released between two frames is never seen as pressed: Enter in a text
// field did nothing when xdotool typed it, or a quick finger during a slow
// frame (1.87 replaced the sampling by an event queue). The gate passes key
// and character events on to ImGui's GLFW callbacks but lets each key change
// state at most once a frame: an event that would change a key a second time
// waits for the next frame, and every event after it waits too, characters
// included, so the order of typing survives. A character after an editing key
// (Backspace, an arrow) waits as well: ImGui inserts a frame's characters
// before acting on its keys.

#include <vector>

struct GLFWwindow;

namespace sdfwb::app::gui {

class KeyGate {
public:
    using KeyCallback = void (*)(GLFWwindow*, int key, int scancode, int action, int mods);
    using CharCallback = void (*)(GLFWwindow*, unsigned int codepoint);

    // Where events go: ImGui's callbacks, as glfwSetKeyCallback and
    // glfwSetCharCallback returned them.
    void setNext(KeyCallback key, CharCallback character);
    void onKey(GLFWwindow* window, int key, int scancode, int action, int mods);
    void onChar(GLFWwindow* window, unsigned int codepoint);
    // Call once a frame, before polling events: delivers what waited.
    void beginFrame(GLFWwindow* window);
    // Events wait for the next frame (which should then come soon).
    bool holding() const { return !held_.empty(); }

private:
    struct Event {
        bool isChar;
        int key, scancode, action, mods;  // key events
        unsigned int codepoint;           // character events
    };
    void deliver(GLFWwindow* window, const Event& event);

    KeyCallback nextKey_ = nullptr;
    CharCallback nextChar_ = nullptr;
    std::vector<int> changedThisFrame_;  // keys pressed or released since beginFrame
    std::vector<Event> held_;            // for the next frame, in order
};

}  // namespace sdfwb::app::gui
