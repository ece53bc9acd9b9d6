#pragma once
// The render panel's quality presets (engine/tradeoff/presets.h) and the
// estimate of how far the current settings are from the reference, from a
// tradeoff sweep's measurements of the scene when there are any; and the step
// relaxation that makes tracing faster at the same error.

#include "tradeoff/measurements.h"
#include "ui/editor.h"
#include "ui/ui_state.h"

namespace sdfwb::ui {

// `measured` is null when no sweep measured the scene.
void drawQualityPresets(Editor& editor, UiState& ui, const tradeoff::SceneMeasurements* measured);

}  // namespace sdfwb::ui
