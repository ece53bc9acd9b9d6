// The key gate holds a release back to the next frame when its key went down
// in this one, so ImGui (which samples keys once a frame) sees every press;
// events keep their order.

#include "app/gui/key_gate.h"

#include <gtest/gtest.h>

#include <GLFW/glfw3.h>

#include <string>
#include <vector>

namespace sdfwb::app::gui {
namespace {

std::vector<std::string> delivered;

void record(GLFWwindow*, int key, int, int action, int) {
    delivered.push_back(std::to_string(key) + (action == GLFW_PRESS ? " down" : action == GLFW_RELEASE ? " up" : " repeat"));
}

struct Gate : ::testing::Test {
    KeyGate gate;
    Gate() {
        delivered.clear();
        gate.setNext(record);
    }
    void key(int key, int action) { gate.onKey(nullptr, key, 0, action, 0); }
    std::vector<std::string> frame() {
        std::vector<std::string> seen = std::exchange(delivered, {});
        gate.beginFrame(nullptr);
        return seen;
    }
};

TEST_F(Gate, ReleaseInThePressFrameWaitsForTheNextFrame) {
    key(GLFW_KEY_ENTER, GLFW_PRESS);
    key(GLFW_KEY_ENTER, GLFW_RELEASE);
    EXPECT_TRUE(gate.holding());
    EXPECT_EQ(frame(), (std::vector<std::string>{"257 down"}));
    EXPECT_FALSE(gate.holding());
    EXPECT_EQ(frame(), (std::vector<std::string>{"257 up"}));
}

TEST_F(Gate, ReleaseInALaterFramePassesAtOnce) {
    key(GLFW_KEY_A, GLFW_PRESS);
    frame();
    key(GLFW_KEY_A, GLFW_REPEAT);
    key(GLFW_KEY_A, GLFW_RELEASE);
    EXPECT_FALSE(gate.holding());
    EXPECT_EQ(frame(), (std::vector<std::string>{"65 repeat", "65 up"}));
}

TEST_F(Gate, QuickDoubleTapTakesFourFramesInOrder) {
    for (int i = 0; i < 2; ++i) {
        key(GLFW_KEY_BACKSPACE, GLFW_PRESS);
        key(GLFW_KEY_BACKSPACE, GLFW_RELEASE);
    }
    EXPECT_EQ(frame(), (std::vector<std::string>{"259 down"}));
    EXPECT_EQ(frame(), (std::vector<std::string>{"259 up", "259 down"}));
    EXPECT_EQ(frame(), (std::vector<std::string>{"259 up"}));
    EXPECT_FALSE(gate.holding());
}

TEST_F(Gate, ModifiersStayDownWhileTheirKeyIsSeen) {
    // Ctrl+A typed between two frames: ImGui must see A with Ctrl held
    key(GLFW_KEY_LEFT_CONTROL, GLFW_PRESS);
    key(GLFW_KEY_A, GLFW_PRESS);
    key(GLFW_KEY_A, GLFW_RELEASE);
    key(GLFW_KEY_LEFT_CONTROL, GLFW_RELEASE);
    EXPECT_EQ(frame(), (std::vector<std::string>{"341 down", "65 down"}));
    EXPECT_EQ(frame(), (std::vector<std::string>{"65 up", "341 up"}));
}

}  // namespace
}  // namespace sdfwb::app::gui
