// The key gate lets each key change state at most once a frame, so ImGui
// (which samples keys once a frame) sees every press and every release; the
// events after one that waits wait too, characters included, in order, and a
// character never shares a frame with an earlier editing key.

#include "app/gui/key_gate.h"

#include <gtest/gtest.h>

#include <GLFW/glfw3.h>

#include <string>
#include <utility>
#include <vector>

namespace sdfwb::app::gui {
namespace {

std::vector<std::string> delivered;

void recordKey(GLFWwindow*, int key, int, int action, int) {
    delivered.push_back(std::to_string(key) + (action == GLFW_PRESS ? " down" : action == GLFW_RELEASE ? " up" : " repeat"));
}

void recordChar(GLFWwindow*, unsigned int codepoint) { delivered.push_back(std::string(1, static_cast<char>(codepoint))); }

struct Gate : ::testing::Test {
    KeyGate gate;
    Gate() {
        delivered.clear();
        gate.setNext(recordKey, recordChar);
    }
    void key(int key, int action) { gate.onKey(nullptr, key, 0, action, 0); }
    void type(char c) { gate.onChar(nullptr, static_cast<unsigned int>(c)); }
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

TEST_F(Gate, QuickDoubleTapTakesFourFrames) {
    for (int i = 0; i < 2; ++i) {
        key(GLFW_KEY_BACKSPACE, GLFW_PRESS);
        key(GLFW_KEY_BACKSPACE, GLFW_RELEASE);
    }
    EXPECT_EQ(frame(), (std::vector<std::string>{"259 down"}));
    EXPECT_EQ(frame(), (std::vector<std::string>{"259 up"}));
    EXPECT_EQ(frame(), (std::vector<std::string>{"259 down"}));
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

TEST_F(Gate, CharactersKeepTheirPlaceBehindWaitingKeys) {
    // "ab", Backspace, "c" typed between two frames must leave "ac"
    type('a');
    type('b');
    key(GLFW_KEY_BACKSPACE, GLFW_PRESS);
    key(GLFW_KEY_BACKSPACE, GLFW_RELEASE);
    type('c');
    EXPECT_EQ(frame(), (std::vector<std::string>{"a", "b", "259 down"}));
    EXPECT_EQ(frame(), (std::vector<std::string>{"259 up"}));
    EXPECT_EQ(frame(), (std::vector<std::string>{"c"}));
}

TEST_F(Gate, TypingLettersTakesNoExtraFrames) {
    for (char c : {'p', 'q'}) {
        key(c - 'a' + GLFW_KEY_A, GLFW_PRESS);
        type(c);
    }
    EXPECT_EQ(frame(), (std::vector<std::string>{"80 down", "p", "81 down", "q"}));
}

TEST_F(Gate, CharacterAfterAnEditingKeyWaitsAFrame) {
    // ImGui would insert the "x" before moving the cursor left
    key(GLFW_KEY_LEFT, GLFW_PRESS);
    type('x');
    EXPECT_EQ(frame(), (std::vector<std::string>{"263 down"}));
    EXPECT_EQ(frame(), (std::vector<std::string>{"x"}));
}

}  // namespace
}  // namespace sdfwb::app::gui
