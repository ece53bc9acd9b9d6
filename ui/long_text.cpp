#include "ui/long_text.h"

#include <algorithm>
#include <cstring>
#include <exception>

#include <imgui.h>
#include <imgui_stdlib.h>

#include "io/atomic_file.h"

namespace sdfwb::ui {
namespace {

bool isContinuationByte(char c) {
    return (static_cast<unsigned char>(c) & 0xC0) == 0x80;
}

// The end of the UTF-8 character that starts at `s`.
const char* nextCharacter(const char* s, const char* end) {
    ++s;
    while (s < end && isContinuationByte(*s)) ++s;
    return s;
}

}  // namespace

std::vector<std::string_view> wrapRows(std::string_view text, float width) {
    ImFont* font = ImGui::GetFont();
    float scale = ImGui::GetFontSize() / font->FontSize;
    width = std::max(width, ImGui::GetFontSize());
    std::vector<std::string_view> rows;
    const char* s = text.data();
    const char* end = s + text.size();
    while (s < end) {
        const char* lineEnd = static_cast<const char*>(std::memchr(s, '\n', static_cast<size_t>(end - s)));
        if (!lineEnd) lineEnd = end;
        if (s == lineEnd) rows.emplace_back();  // an empty line
        while (s < lineEnd) {
            const char* cut = font->CalcWordWrapPositionA(scale, s, lineEnd, width);
            if (cut <= s) cut = nextCharacter(s, lineEnd);  // a glyph wider than the row still moves on
            rows.emplace_back(s, static_cast<size_t>(cut - s));
            s = cut;
            while (s < lineEnd && (*s == ' ' || *s == '\t')) ++s;  // the blanks a row breaks at
        }
        s = lineEnd + 1;
    }
    return rows;
}

void wrappedText(std::string_view text, float width) {
    std::vector<std::string_view> rows = wrapRows(text, width > 0 ? width : ImGui::GetContentRegionAvail().x);
    // rows of one wrapped paragraph sit without item spacing, as TextWrapped's
    ImGui::PushStyleVar(ImGuiStyleVar_ItemSpacing, ImVec2(ImGui::GetStyle().ItemSpacing.x, 0));
    ImGuiListClipper clipper;
    clipper.Begin(static_cast<int>(rows.size()), ImGui::GetTextLineHeight());
    while (clipper.Step()) {
        for (int i = clipper.DisplayStart; i < clipper.DisplayEnd; ++i) {
            std::string_view row = rows[static_cast<size_t>(i)];
            ImGui::TextUnformatted(row.data(), row.data() + row.size());
        }
    }
    ImGui::PopStyleVar();
    ImGui::Dummy(ImVec2(0, 0));  // the usual spacing after the paragraph
}

bool oneLineText(std::string_view text, float width) {
    std::string_view line = text.substr(0, text.find('\n'));
    ImFont* font = ImGui::GetFont();
    const char* begin = line.data();
    const char* end = begin + line.size();
    const char* fits = end;
    font->CalcTextSizeA(ImGui::GetFontSize(), width, 0, begin, end, &fits);
    bool cut = fits < end || line.size() < text.size();
    if (!cut) {
        ImGui::TextUnformatted(begin, end);
        return false;
    }
    const char* ellipsis = "...";
    float room = width - ImGui::CalcTextSize(ellipsis).x;
    font->CalcTextSizeA(ImGui::GetFontSize(), std::max(room, 0.0f), 0, begin, end, &fits);
    std::string shown = std::string(begin, fits) + ellipsis;
    ImGui::TextUnformatted(shown.c_str());
    return true;
}

std::string saveText(const std::filesystem::path& path, std::string_view text) {
    if (path.empty()) return "type a file name to save to";
    try {
        io::writeTextAtomically(path, text);
    } catch (const std::exception& error) {
        return error.what();
    }
    return {};
}

void longTextBox(const char* id, std::string_view text, float height, LongTextBoxState& state) {
    ImGui::PushID(id);
    float controls = ImGui::GetFrameHeightWithSpacing() * (state.saveMessage.empty() ? 1.0f : 2.0f);
    if (height <= 0) height = std::max(ImGui::GetContentRegionAvail().y - controls, ImGui::GetTextLineHeight() * 3);
    ImGui::BeginChild("text", ImVec2(-1, height), true);
    wrappedText(text);
    ImGui::EndChild();
    if (ImGui::Button("Copy")) ImGui::SetClipboardText(std::string(text).c_str());
    ImGui::SameLine();
    bool enter = false;
    ImGui::SetNextItemWidth(std::max(ImGui::GetContentRegionAvail().x - 220, 80.0f));
    enter = ImGui::InputTextWithHint("##save path", "file to save the full text to", &state.savePath,
                                     ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::SameLine();
    if (ImGui::Button("Save") || enter) {
        std::string problem = saveText(state.savePath, text);
        state.saveFailed = !problem.empty();
        state.saveMessage = problem.empty() ? "saved " + std::to_string(text.size()) + " characters to " + state.savePath
                                            : problem;
    }
    ImGui::SameLine();
    ImGui::TextDisabled("%zu characters", text.size());
    if (!state.saveMessage.empty()) {
        ImVec4 colour = state.saveFailed ? ImVec4(1, 0.43f, 0.39f, 1) : ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled);
        ImGui::PushStyleColor(ImGuiCol_Text, colour);
        wrappedText(state.saveMessage);
        ImGui::PopStyleColor();
    }
    ImGui::PopID();
}

std::string shortened(std::string_view text, std::size_t maxChars) {
    std::size_t keep = std::min({text.size(), maxChars, text.find('\n')});
    if (keep == text.size()) return std::string(text);
    while (keep > 0 && isContinuationByte(text[keep])) --keep;
    return std::string(text.substr(0, keep)) + " ... (" + std::to_string(text.size()) + " characters)";
}

}  // namespace sdfwb::ui
