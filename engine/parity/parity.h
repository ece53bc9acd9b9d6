#pragma once
// CPU/GPU parity of one scene: both backends render it at the same settings and
// the images are compared on the display encoding. Hard cases (scenes/hard/)
// are also measured against a double-precision CPU reference with a tight
// epsilon. The parity command and the parity tests share this code.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "image/compare.h"
#include "parity/polynomial_reference.h"
#include "parity/reference_agreement.h"
#include "render/render_backend.h"
#include "scene/scene.h"

namespace sdfwb::parity {

struct ParityOptions {
    int width = 320;
    int height = 180;
    int aa = 2;
    bool reference = false;  // also render the double-precision reference (hard cases)
    // The reference's hit epsilon is the scene's divided by this, and its step
    // limits are multiplied by it (up to the largest valid values), so that it
    // converges where the scene's settings stop early.
    double referenceTightening = 10.0;
    // The intended result of a hard case when the scene itself cannot give it
    // (both precisions make the same mistake, e.g. a film on a flush cut): the
    // reference is rendered from this scene instead (intendedSceneFile()).
    const scene::Scene* intended = nullptr;
};

// scenes/hard/intended/NAME.json, a construction of what scenes/hard/NAME.json
// should look like that avoids the scene's difficulty, when it exists.
// Throws what the scene loader throws.
std::optional<scene::Scene> loadIntendedScene(const std::filesystem::path& hardScene);

struct ParityResult {
    image::Image cpuColor;  // the renders compared, for a failure's images (writeFailureImages)
    image::Image glColor;
    image::Comparison glVsCpu;
    double cpuSeconds = 0;
    double glSeconds = 0;
    double cpuHitRatio = 0;
    double glHitRatio = 0;
    size_t cpuNonFinite = 0;
    size_t glNonFinite = 0;
    bool passes = false;  // the parity thresholds of image/compare.h

    // With ParityOptions::reference:
    bool hasReference = false;
    image::Comparison cpuVsReference;
    image::Comparison glVsReference;
    double referenceHitRatio = 0;
    bool intendedReference = false;  // the references came from ParityOptions::intended
    // Per pixel against the double build at the scene's own settings (float
    // against double: precision alone; what the gate judges), and against the
    // tightened reference (convergence, colour edges counted apart as a
    // tighter epsilon moves them; reported only: thin features shade
    // differently at a tenth of the epsilon, 8 % of thin_shell's pixels).
    ReferenceAgreement cpuAgreement;
    ReferenceAgreement glAgreement;
    ReferenceAgreement cpuConverged;
    ReferenceAgreement glConverged;
    bool passesHardGate = false;  // see hardGate()

    // For a polynomial surface (polynomialScene()): each backend at AA 1 against
    // the first-root reference (polynomial_reference.h).
    std::optional<PolynomialAccuracy> cpuPolynomial;
    std::optional<PolynomialAccuracy> glPolynomial;
};

// Renders `scene` with `cpu`, the reference (float; double for the
// reference of a hard case), and with `gl`, the backend checked against it,
// and compares. Throws what the backends throw.
ParityResult measureParity(const scene::Scene& scene, render::Backend& cpu, render::Backend& gl,
                           const ParityOptions& options);

// Limits of the hard-case gate, on ReferenceAgreement's figures.
struct HardGateThresholds {
    double interiorErrorPercent = 0.5;   // pixels off the silhouettes beyond 8/255 of the double build
    double interiorMaskPercent = 0.1;    // holes and films off the geometric outlines, by coverage or depth
    double silhouetteMaskPercent = 1.5;  // outlines moved by more than a pixel
};
inline constexpr HardGateThresholds kHardGateThresholds{};

// The hard-case gate: no NaN; GL against CPU within the regular parity
// thresholds; each backend against the double build at the scene's settings
// (or the intended scene's) within kHardGateThresholds; GL mean error against
// the tightened reference at most 1.25 x the CPU float backend's plus 1/255.
bool hardGate(const ParityResult& result);

// A failed comparison's evidence in `folder`: NAME-expected.png (the CPU
// render), NAME-actual.png (the GL render) and NAME-diff.png (their
// differenceHeatImage, full scale at the hard-fail level). Returns the paths;
// throws what writing an image throws.
std::vector<std::filesystem::path> writeFailureImages(const ParityResult& result, const std::filesystem::path& folder,
                                                      const std::string& name);

// Markdown table header and one row per scene.
std::string tableHeader(bool withReference);
std::string tableRow(const std::string& sceneName, const ParityResult& result, bool withReference);

}  // namespace sdfwb::parity
