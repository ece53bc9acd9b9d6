#include "app/gui/view_choice.h"

#include <algorithm>
#include <cmath>

namespace sdfwb::app::gui {

bool refinesInPlace(const ImageContent& texture, std::uint64_t state) { return texture.state == state; }

bool drawsCompiled(bool asked, std::uint64_t compiledState, std::uint64_t shownState, bool interacting,
                   bool fitsTexture) {
    return asked || (interacting && compiledState != shownState && fitsTexture);
}

SlotView chooseSlot(Source wanted, const ImageContent (&textures)[kSources], std::uint64_t state, bool interacting) {
    const Source other = wanted == Source::Gl ? Source::Cpu : Source::Gl;
    const ImageContent& mine = textures[static_cast<int>(wanted)];
    const ImageContent& theirs = textures[static_cast<int>(other)];
    if (mine.state == state) return {wanted, SlotView::Note::None};
    if (theirs.state == state) return {other, SlotView::Note::StandIn};
    if (!mine.empty()) return {wanted, interacting ? SlotView::Note::None : SlotView::Note::Outdated};
    if (!theirs.empty()) return {other, interacting ? SlotView::Note::None : SlotView::Note::Outdated};
    return {wanted, SlotView::Note::Empty};
}

LanePlan planLanes(Source wanted, bool compare, bool glReady, bool glFailed) {
    LanePlan plan;
    plan.renders[static_cast<int>(wanted)] = true;
    if (compare) {
        plan.renders[static_cast<int>(Source::Gl)] = plan.renders[static_cast<int>(Source::Cpu)] = true;
    } else if (wanted == Source::Gl && (!glReady || glFailed)) {
        plan.renders[static_cast<int>(Source::Cpu)] = true;
        plan.standIn = true;
    }
    if (glFailed) plan.renders[static_cast<int>(Source::Gl)] = false;
    return plan;
}

double previewSecondsPerSample(double lastStage, double wholeProgram, bool gridPending) {
    return gridPending ? std::max(lastStage, wholeProgram) : lastStage;
}

int previewScale(double pixels, double secondsPerSample) {
    if (secondsPerSample <= 0 || pixels <= 0) return kCoarsestPreview;
    double scale = std::ceil(std::sqrt(pixels * secondsPerSample / kPreviewSeconds));
    return static_cast<int>(std::clamp(scale, 2.0, static_cast<double>(kCoarsestPreview)));
}

}  // namespace sdfwb::app::gui
