#pragma once
// ImGui 1.86 samples the keyboard once a frame (io.KeysDown), so a key pressed
// and released between two frames is never seen as pressed: Enter in a text
// field did nothing when xdotool typed it, or a quick finger during a slow
// frame (1.87 replaced the sampling by an event queue). The gate passes key
// events on to ImGui's GLFW callback but holds a release back to the next
// frame when the key went down in this one, and every event after it.

#include <vector>

struct GLFWwindow;

namespace sdfwb::app::gui {

class KeyGate {
public:
    using Callback = void (*)(GLFWwindow*, int key, int scancode, int action, int mods);

    // Where events go: ImGui's callback, as glfwSetKeyCallback returned it.
    void setNext(Callback next) { next_ = next; }
    void onKey(GLFWwindow* window, int key, int scancode, int action, int mods);
    // Call once a frame, before polling events: delivers the held releases.
    void beginFrame(GLFWwindow* window);
    // Events wait for the next frame (which should then come soon).
    bool holding() const { return !held_.empty(); }

private:
    struct Event {
        int key, scancode, action, mods;
    };
    Callback next_ = nullptr;
    std::vector<int> downThisFrame_;  // passed on as pressed since beginFrame
    std::vector<Event> held_;         // for the next frame, in order
};

}  // namespace sdfwb::app::gui
