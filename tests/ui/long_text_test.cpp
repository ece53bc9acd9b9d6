// Long text never overflows a draw list (issue 13, item 1): wrapped rows,
// the polynomial window with a 16 K character result, errors of any length,
// and the full text saved to a file.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include <imgui.h>

#include "io/atomic_file.h"
#include "support/headless_imgui.h"
#include "support/source_tree.h"
#include "ui/long_text.h"
#include "ui/panel_widgets.h"
#include "ui/polynomial_panel.h"

namespace sdfwb::ui {
namespace {

// The largest vertex count of one draw list in the frame just rendered.
int largestDrawList() {
    int largest = 0;
    ImDrawData* data = ImGui::GetDrawData();
    for (int i = 0; i < data->CmdListsCount; ++i) largest = std::max(largest, data->CmdLists[i]->VtxBuffer.Size);
    return largest;
}

std::string longWords(std::size_t characters) {
    std::string text;
    for (int i = 0; text.size() < characters; ++i) text += "x^" + std::to_string(i % 97) + "*y ";
    return text;
}

class LongTextTest : public ::testing::Test {
protected:
    test::HeadlessImGui imgui;
};

TEST_F(LongTextTest, RowsFitTheWidthAndKeepEveryCharacter) {
    ImGui::NewFrame();
    std::string text = longWords(5000) + "\n\n" + std::string(3000, 'w') + "\nend";
    const float width = 300;
    std::vector<std::string_view> rows = wrapRows(text, width);
    std::string joined;
    for (std::string_view row : rows) {
        EXPECT_LE(ImGui::CalcTextSize(row.data(), row.data() + row.size()).x, width);
        joined += row;
    }
    std::string withoutBreaks;
    for (char c : text) if (c != ' ' && c != '\n') withoutBreaks += c;
    std::erase(joined, ' ');
    EXPECT_EQ(joined, withoutBreaks);
    EXPECT_GT(rows.size(), 3000u * 7 / 300);  // the long word is cut into rows too
    EXPECT_TRUE(std::find(rows.begin(), rows.end(), std::string_view()) != rows.end());  // the empty line
    ImGui::EndFrame();
}

TEST_F(LongTextTest, ErrorsOfAnyLengthStayWithinOneDrawList) {
    std::string problem = "column 3: " + longWords(200000);
    for (int frame = 0; frame < 2; ++frame) {
        ImGui::NewFrame();
        ImGui::SetNextWindowSize(ImVec2(400, 300));
        ImGui::Begin("errors");
        problemText(problem);
        oneLineText(problem, 300);
        ImGui::End();
        ImGui::Render();
        EXPECT_LT(largestDrawList(), 20000);
    }
}

TEST_F(LongTextTest, PolynomialWindowShowsA16KResultAndSavesItWhole) {
    PolynomialPanelState state;
    state.open = true;
    state.request.equations = "x = (u+v+1)^40; y = v; z = u";
    readParameters(state);
    ASSERT_EQ(state.problem, "");
    runPolynomial(state);
    state.job.wait();
    std::optional<PolynomialOutcome> outcome = state.job.outcome();
    ASSERT_TRUE(outcome && outcome->isSurface()) << (outcome ? outcome->message : "no outcome");
    const std::string& generator = outcome->generators.front();
    ASSERT_GT(generator.size(), 16000u);

    Editor editor;
    UiState ui;
    for (int frame = 0; frame < 3; ++frame) {
        ImGui::NewFrame();
        drawPolynomialPanel(editor, ui, state, ImVec2(0, 0), ImGui::GetIO().DisplaySize);
        ImGui::Render();
        EXPECT_LT(largestDrawList(), 20000);
    }

    // The output folder exists only after tests that made it: make it here, so the test passes alone.
    std::filesystem::create_directories(sdfwb::test::outputDir());
    std::filesystem::path file = std::filesystem::path(sdfwb::test::outputDir()) / "long_text_result.txt";
    EXPECT_EQ(saveText(file, generator + " = 0"), "");
    EXPECT_EQ(io::readTextFile(file), generator + " = 0");
    EXPECT_NE(saveText("/nonexistent-folder/result.txt", generator), "");
    EXPECT_NE(saveText("", generator), "");
}

TEST(Shortened, KeepsShortTextAndCutsLongTextAtACharacter) {
    EXPECT_EQ(shortened("short", 10), "short");
    EXPECT_EQ(shortened("first\nsecond", 100), "first ... (12 characters)");
    EXPECT_EQ(shortened("aé", 2), "a ... (3 characters)");  // not inside the two bytes of é
}

}  // namespace
}  // namespace sdfwb::ui
