#pragma once
// Text of any length (polynomial results, error messages, formulas echoed in
// errors, names) drawn so that it can never overflow a window's draw list.
//
// Why: Dear ImGui 1.86 emits a vertex quad for every glyph of a wrapped text
// (TextWrapped skips no rows above or below the clip rectangle), and a window's
// draw list holds 64 K vertices with 16-bit indices: a 16 K character result in
// TextWrapped aborted the application. These widgets wrap the text themselves
// and hand ImGui only the rows in view, so the vertex count is bounded by the
// visible area whatever the length.

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace sdfwb::ui {

// The rows `text` wraps into at `width` pixels with the current font: breaks
// at newlines and at word boundaries (inside a word longer than a row).
std::vector<std::string_view> wrapRows(std::string_view text, float width);

// Wrapped text `width` pixels wide (0: the window's content width), in the
// current text colour; only the rows in the window's view are drawn.
void wrappedText(std::string_view text, float width = 0);

// The first line of `text` cut to `width` pixels with "..." when it is longer
// (or has more lines); returns whether anything was left out.
bool oneLineText(std::string_view text, float width);

// What a long-text box keeps between frames: the path typed for "Save".
struct LongTextBoxState {
    std::string savePath;
    std::string saveMessage;  // the last save's outcome ("saved ...", or why not)
    bool saveFailed = false;
};

// A framed, scrolled box `height` pixels high (0: the rest of the window)
// showing `text` wrapped, with Copy (to the clipboard) and Save (the full text
// to the typed file, atomically) under it.
void longTextBox(const char* id, std::string_view text, float height, LongTextBoxState& state);

// Writes `text` to `path` atomically; returns "" or the reason it failed.
std::string saveText(const std::filesystem::path& path, std::string_view text);

// At most `maxChars` bytes of `text` (cut at a UTF-8 boundary) and, when cut,
// "... (N characters)": for one-line places (status bar, tooltips) that must
// stay short whatever the message.
std::string shortened(std::string_view text, std::size_t maxChars);

}  // namespace sdfwb::ui
