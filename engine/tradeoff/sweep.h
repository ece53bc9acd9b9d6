#pragma once
// The speed-against-error sweep: for each scene, renders the reference once
// (cached), then every planned setting with each backend, timing several
// repetitions with the backends interleaved, and measures steps per pixel and
// the error against the reference.

#include <atomic>
#include <filesystem>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "render/render_backend.h"
#include "tradeoff/frame_error.h"
#include "tradeoff/reference.h"
#include "tradeoff/sweep_plan.h"

namespace sdfwb::tradeoff {

struct SceneInput {
    std::string name;  // as the report shows it (e.g. the file's path under the scene folder)
    scene::Scene scene;
};

struct SweepProgress {
    int scenesDone = 0;
    int scenesTotal = 0;
    int settingsDone = 0;  // over all scenes, skipped ones included
    int settingsTotal = 0;
    double elapsedSeconds = 0;
    double secondsLeft = -1;  // estimate; negative until one setting was measured
    std::string current;      // "scene: setting"
};

struct SweepOptions {
    int width = 320;
    int height = 180;
    int repetitions = 3;  // timed renders per setting and backend; the median is reported
    double budgetSeconds = std::numeric_limits<double>::infinity();  // wall time; then the rest is skipped
    // After the one-knob settings, a "tuned" setting combines each knob's fastest
    // value within this many levels of 255 (mean) of the default's error; when
    // it relaxes steps, the same without relaxation is measured too.
    double tuningSlack = 0.5;
    ReferenceOptions reference;
    std::filesystem::path cacheDir;
    const std::atomic<bool>* cancel = nullptr;
    std::function<void(const SweepProgress&)> progress;
};

struct Measurement {
    double seconds = 0;  // median of the repetitions
    std::vector<double> repetitionSeconds;
    double meanSteps = 0;  // primary-march evaluations per pixel (per sub-sample, averaged)
    double maxSteps = 0;
    double meanEvaluations = 0;  // all field evaluations (march, normal, material, AO, shadow) per pixel, likewise
    FrameError error;
};

struct SettingResult {
    Setting setting;
    std::vector<Measurement> byBackend;  // in the order of the sweep's backends
};

// Over the result's backends: the sum of their times, and the largest of
// their mean display errors (what the tuning and the suggested default weigh).
double totalSeconds(const SettingResult& result);
double worstMeanError(const SettingResult& result);

struct SceneResult {
    std::string name;
    scene::Scene scene;  // at the measured size
    scene::Scene reference;
    bool referenceCached = false;
    double referenceSeconds = 0;
    std::vector<SettingResult> results;  // [0] is the default when anything was measured
    std::vector<SkippedKnob> notSwept;   // inert knobs, and knobs whose cheapest value changed nothing
    std::vector<std::string> skipped;    // settings left out by the budget
};

struct SweepResult {
    std::vector<std::string> backends;
    std::vector<SceneResult> scenes;
    bool cancelled = false;  // interrupted: the result is partial
    bool budgetExhausted = false;
    double seconds = 0;
};

// Each backend's prepare() (shader build and warm-up) runs before its timed
// renders. Throws what the backends and the reference cache throw.
SweepResult runSweep(const std::vector<SceneInput>& scenes, const std::vector<KnobRequest>& knobs,
                     const std::vector<render::Backend*>& backends, const SweepOptions& options);

}  // namespace sdfwb::tradeoff
