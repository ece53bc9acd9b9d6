#pragma once
// The viewport's decisions, apart from GL and threads so tests can drive
// them: which backends render for the current request, which image each
// view slot shows, and whether a render may refine a texture tile by tile.
//
// The rule they keep: the viewport never shows an image of another scene
// state than the current one without saying so, and never a mix of two
// states. A state is what the image depends on (the scene revision, the
// image size, the step-heat view), not which backend draws it.

#include <cstdint>

namespace sdfwb::app::gui {

enum class Source { Gl = 0, Cpu = 1 };
constexpr int kSources = 2;

// What one backend's texture holds.
struct ImageContent {
    std::uint64_t state = 0;  // the state it shows; 0: nothing yet
    int stage = -1;           // the last stage completed for it
    bool empty() const { return state == 0; }
};

// A render's tiles may go straight into the texture when it already holds
// the same state (a preview or a lower AA is refined); otherwise they wait
// and the finished stage replaces the image at once.
bool refinesInPlace(const ImageContent& texture, std::uint64_t state);

// Whether a lane draws a program just compiled: the one it asked for; or,
// during a drag, where each frame asks for a new state and its program comes
// a frame or more later, the freshest compiled for another state than the
// texture shows, as the drag's preview, when its image still fits the
// texture (the view was not resized meanwhile). After the drag a late
// program of an older state is not drawn.
bool drawsCompiled(bool asked, std::uint64_t compiledState, std::uint64_t shownState, bool interacting,
                   bool fitsTexture);

// What a view slot draws and what it must say about it.
struct SlotView {
    Source shown = Source::Gl;
    enum class Note {
        None,      // the wanted backend's image of the current state
        StandIn,   // the other backend's image of the current state, until the wanted one is ready
        Outdated,  // an image of an earlier state, while the current one renders
        Empty,     // nothing rendered yet
    } note = Note::None;
};

// The slot that wants `wanted`'s image of `state`, given what both textures
// hold. While `interacting` (a drag) the last preview follows within a frame
// or two, so an older image is shown without the Outdated note.
SlotView chooseSlot(Source wanted, const ImageContent (&textures)[kSources], std::uint64_t state, bool interacting);

// Which backends render for a request: the wanted one, both when comparing,
// and the CPU standing in while the GL program of a new structure builds or
// when it failed (the CPU reference always works). A stand-in stops as soon
// as the GL backend is ready, so the cores go to the faster path.
struct LanePlan {
    bool renders[kSources] = {false, false};
    bool standIn = false;  // the CPU renders in place of the GL backend
};
LanePlan planLanes(Source wanted, bool compare, bool glReady, bool glFailed);

// A preview's price per sample (pixel x AA sub-sample). A lane measures two:
// its last stage's, and its last whole-program render's (a large scene's
// preview drawn before the prune grid of an edit is built evaluates every
// primitive at every step: many times the pruned stage's cost). While the
// scene's grid may still be missing (an edit since the last full-size stage,
// which waits for it; prune/grid_edits.h) the preview is priced as a
// whole-program render, once one was measured; after a relight, a resize or
// a change of backend the grid is there.
double previewSecondsPerSample(double lastStage, double wholeProgram, bool gridPending);

// The scale (width / scale x height / scale) of the largest preview costing
// about kPreviewSeconds at that price; at least half resolution, at most
// 1/kCoarsestPreview, which is also the first preview's, before anything is
// measured: a scene just opened may be the 1001-sphere molecule, whose
// whole program costs about 0.7 ms a sample on llvmpipe's 2 cores (27 s at a
// quarter of an 882 x 704 view, 0.42 s at 1/32).
inline constexpr double kPreviewSeconds = 0.05;
inline constexpr int kCoarsestPreview = 32;
int previewScale(double pixels, double secondsPerSample);

}  // namespace sdfwb::app::gui
