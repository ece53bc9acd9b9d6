#pragma once
// Selection in the viewport: a click (press and release without a drag)
// selects the node under the pixel, the selection is outlined over the image
// with its move, rotate or scale handles (ui/transform_handles.h), and a readout shows what the pixel under the cursor holds (distance, steps,
// node). All picks come from the shared CPU path (cpu/pick.h).

#include <optional>
#include <string>

#include <imgui.h>

#include "cpu/pick.h"

namespace sdfwb::app::gui {

struct AppState;

// What the cursor was over when last picked, so a still mouse costs nothing.
struct PixelReadout {
    ImVec2 mouse{-1, -1};
    std::uint64_t revision = 0;
    std::optional<cpu::PickResult> pick;
};

// The image pixel (framebuffer pixels from the top left) under a screen point.
ImVec2 imagePixel(const AppState& app, ImVec2 corner, ImVec2 size, ImVec2 screen);

// Call right after the viewport's camera button (the last item), with the
// image's screen rectangle.
void viewSelection(AppState& app, ImVec2 corner, ImVec2 size);

}  // namespace sdfwb::app::gui
