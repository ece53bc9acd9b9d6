// Fuzz target: the GUI script parser (ui/script.h). Text either parses or
// fails with std::runtime_error naming the line.

#include <cstdint>
#include <stdexcept>
#include <string_view>

#include "ui/script.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        sdfwb::ui::parseScript(text, "fuzz");
    } catch (const std::runtime_error&) {
    }
    return 0;
}
