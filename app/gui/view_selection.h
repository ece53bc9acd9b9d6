#pragma once
// Selection in the viewport: a click (press and release without a drag)
// selects the node under the pixel, the selection is outlined over the image
// with its move, rotate or scale handles (ui/transform_handles.h), and a readout shows what the pixel under the cursor holds (distance, steps,
// node). All picks come from the shared CPU path (cpu/pick.h), on a worker.

#include <optional>
#include <string>

#include <imgui.h>

#include "ui/pixel_probe.h"

namespace sdfwb::app::gui {

struct AppState;

// The viewport's picks, off the UI thread (ui/pixel_probe.h): the readout's
// for the pixel under the cursor, and the click's (never superseded by the
// cursor moving on), sharing one compiled program per scene state.
struct ViewPicks {
    ui::PixelProbe readout;
    ui::PixelProbe click{readout.programs()};
    bool clickPending = false;  // a click's pick selects when it is ready
};

// The image pixel (framebuffer pixels from the top left) under a screen point.
ImVec2 imagePixel(const AppState& app, ImVec2 corner, ImVec2 size, ImVec2 screen);

// Call right after the viewport's camera button (the last item), with the
// image's screen rectangle.
void viewSelection(AppState& app, ImVec2 corner, ImVec2 size);

}  // namespace sdfwb::app::gui
