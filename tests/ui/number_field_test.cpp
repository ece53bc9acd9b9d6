// Typing into a number field (Ctrl+click on a drag field), driven through a
// headless ImGui 1.86 context as a user's mouse and keys would: ImGui applies
// the text as it is typed, so "1e999" passed through "1e99" and left it in the
// scene under a "not a number" error; and the field's number filter dropped
// "nan", "inf" and letters without a word (issue 13, item 8).

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/headless_imgui.h"
#include "ui/panel_widgets.h"

namespace sdfwb::ui {
namespace {

constexpr int kEnterKey = 13;  // our index for ImGuiKey_Enter in io.KeysDown

class NumberField : public ::testing::Test {
protected:
    NumberField() { ImGui::GetIO().KeyMap[ImGuiKey_Enter] = kEnterKey; }

    // One frame drawing the field; returns its edit, remembers its centre.
    WidgetEdit frame() {
        ImGui::NewFrame();
        ImGui::SetNextWindowPos(ImVec2(10, 10));
        ImGui::SetNextWindowSize(ImVec2(400, 200));
        ImGui::Begin("panel");
        WidgetEdit edit = dragReal("radius", value, 0.01, 0.0, 1e99);
        ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
        centre = ImVec2((min.x + max.x) / 2, (min.y + max.y) / 2);
        ImGui::End();
        ImGui::Render();
        ImGuiIO& io = ImGui::GetIO();
        io.MouseDown[0] = false;
        io.KeyCtrl = false;
        io.KeysDown[kEnterKey] = false;
        edits.push_back(edit);
        return edit;
    }

    void ctrlClick() {
        frame();  // lays the field out
        ImGuiIO& io = ImGui::GetIO();
        io.MousePos = centre;
        frame();  // hovered
        io.MousePos = centre;
        io.KeyCtrl = true;
        io.MouseDown[0] = true;
        frame();
        frame();  // released: typing now
    }

    // Each character in a frame of its own, as keys come.
    void type(const std::string& text) {
        for (char c : text) {
            ImGui::GetIO().AddInputCharacter(static_cast<unsigned>(c));
            frame();
        }
    }

    WidgetEdit enter() {
        ImGui::GetIO().KeysDown[kEnterKey] = true;
        WidgetEdit edit = frame();
        frame();
        return edit;
    }

    std::string reported() const {
        std::string all;
        for (const WidgetEdit& e : edits) {
            if (!e.notANumber.empty()) all += "[" + e.notANumber + "]";
        }
        return all;
    }

    test::HeadlessImGui imgui;
    double value = 0.8;
    ImVec2 centre;
    std::vector<WidgetEdit> edits;
};

TEST_F(NumberField, AFiniteNumberTypedIsTheNewValue) {
    ctrlClick();
    type("2.5");
    WidgetEdit last = enter();
    EXPECT_DOUBLE_EQ(value, 2.5);
    EXPECT_TRUE(last.finished);
    EXPECT_EQ(reported(), "");
}

TEST_F(NumberField, AnOverflowingNumberPutsBackTheValueFromBeforeTyping) {
    ctrlClick();
    type("1e999");  // "1e99" on the way is a finite value ImGui applies
    WidgetEdit last = enter();
    EXPECT_DOUBLE_EQ(value, 0.8) << "the value before typing, not 1e99";
    EXPECT_EQ(last.notANumber, "1e999");
    EXPECT_TRUE(last.changed) << "the value put back is an edit of the value on the way";
    EXPECT_TRUE(last.finished);
}

TEST_F(NumberField, LettersTheFieldDropsAreSaidAsTheyAreTyped) {
    ctrlClick();
    type("nan");
    EXPECT_EQ(reported(), "[n][na][nan]") << "each dropped key at once";
    enter();
    EXPECT_DOUBLE_EQ(value, 0.8);
}

}  // namespace
}  // namespace sdfwb::ui
