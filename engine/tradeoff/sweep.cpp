#include "tradeoff/sweep.h"

#include <algorithm>
#include <chrono>

#include "program/compile_scene.h"
#include "tradeoff/measurements.h"

namespace sdfwb::tradeoff {
namespace {

using Clock = std::chrono::steady_clock;

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    size_t n = values.size();
    return n == 0 ? 0.0 : n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

bool sameImage(const image::Frame& a, const image::Frame& b) {
    return a.color.rgb == b.color.rgb && a.steps == b.steps;
}

struct TimedFrame {
    image::Frame frame;
    double seconds = 0;
};

// The render alone, without what prepare() built; nothing when cancelled.
std::optional<TimedFrame> timedRender(render::Backend& backend, const program::Program& program,
                                      const std::atomic<bool>* cancel) {
    render::RenderControl control;
    control.cancel = cancel;
    auto start = Clock::now();
    render::RenderOutcome outcome = backend.render(program, control);
    if (outcome.cancelled) return std::nullopt;
    return TimedFrame{std::move(outcome.frame), std::chrono::duration<double>(Clock::now() - start).count()};
}

class Sweep {
public:
    Sweep(const std::vector<render::Backend*>& backends, const SweepOptions& options)
        : backends_(backends), options_(options), start_(Clock::now()) {}

    double elapsed() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }
    bool cancelled() const { return options_.cancel != nullptr && options_.cancel->load(); }
    bool outOfTime() const { return elapsed() >= options_.budgetSeconds; }

    // One unit of work done (a reference or a setting); `measured` when it took rendering time.
    void advance(const std::string& current, bool measured) {
        ++progress.settingsDone;
        if (measured) ++measuredUnits_;
        report(current);
    }

    void report(const std::string& current) {
        if (!options_.progress) return;
        progress.elapsedSeconds = elapsed();
        progress.current = current;
        int left = progress.settingsTotal - progress.settingsDone;
        progress.secondsLeft = measuredUnits_ > 0 ? progress.elapsedSeconds / measuredUnits_ * left : -1;
        options_.progress(progress);
    }

    SweepProgress progress;

    // Renders `setting` with every backend, `repetitions` times interleaved.
    // Nothing when cancelled.
    std::optional<std::pair<SettingResult, image::Frame>> measure(const Setting& setting,
                                                                  const image::Frame& reference) {
        program::Program program = program::compileScene(setting.scene);
        SettingResult result{setting, std::vector<Measurement>(backends_.size())};
        image::Frame first;
        for (int rep = 0; rep < std::max(1, options_.repetitions); ++rep) {
            for (size_t b = 0; b < backends_.size(); ++b) {
                std::optional<TimedFrame> timed = timedRender(*backends_[b], program, options_.cancel);
                if (!timed) return std::nullopt;
                Measurement& m = result.byBackend[b];
                m.repetitionSeconds.push_back(timed->seconds);
                if (rep > 0) continue;  // renders are deterministic: measure the first
                image::FrameStats stats = image::frameStats(timed->frame);
                m.meanSteps = stats.meanSteps;
                m.maxSteps = stats.maxSteps;
                m.meanEvaluations = stats.meanEvaluations;
                m.error = frameError(timed->frame, reference);
                if (b == 0) first = std::move(timed->frame);
            }
        }
        for (Measurement& m : result.byBackend) m.seconds = median(m.repetitionSeconds);
        return std::make_pair(std::move(result), std::move(first));
    }

private:
    const std::vector<render::Backend*>& backends_;
    const SweepOptions& options_;
    Clock::time_point start_;
    int measuredUnits_ = 0;
};

scene::Scene atMeasuredSize(scene::Scene scene, const SweepOptions& options) {
    scene.render.width = options.width;
    scene.render.height = options.height;
    return scene;
}

// The one-knob results combined (sweep_plan.h: tunedSetting).
std::optional<Setting> tuned(const SceneResult& sr, const SweepOptions& options) {
    if (sr.results.size() < 2) return std::nullopt;
    std::vector<TuningCandidate> candidates;
    for (const SettingResult& r : sr.results) candidates.push_back({&r.setting, totalSeconds(r), worstMeanError(r)});
    return tunedSetting(sr.scene, candidates, totalSeconds(sr.results[0]), worstMeanError(sr.results[0]),
                        options.tuningSlack);
}

// What the workbench reads back (measurements.h).
SceneMeasurements measurementsOf(const SceneResult& sr, const std::vector<std::string>& backends) {
    SceneMeasurements m{backends, {}};
    for (const SettingResult& r : sr.results) {
        MeasuredPoint p{r.setting.scene.render, {}, worstMeanError(r)};
        for (const Measurement& b : r.byBackend) p.seconds.push_back(b.seconds);
        m.points.push_back(std::move(p));
    }
    return m;
}

// Most AA any planned setting uses: the reference resolves at least that finely.
int largestAa(const SweepPlan& plan) {
    int aa = 1;
    for (const Setting& s : plan.settings) aa = std::max(aa, s.scene.render.aa);
    return aa;
}

}  // namespace

double totalSeconds(const SettingResult& result) {
    double sum = 0;
    for (const Measurement& m : result.byBackend) sum += m.seconds;
    return sum;
}

double worstMeanError(const SettingResult& result) {
    double worst = 0;
    for (const Measurement& m : result.byBackend) worst = std::max(worst, m.error.display.meanAbs);
    return worst;
}

SweepResult runSweep(const std::vector<SceneInput>& scenes, const std::vector<KnobRequest>& knobs,
                     const std::vector<render::Backend*>& backends, const SweepOptions& options) {
    Sweep sweep(backends, options);
    SweepResult result;
    for (render::Backend* backend : backends) result.backends.push_back(backend->name());

    std::vector<SweepPlan> plans;
    for (const SceneInput& input : scenes) {
        plans.push_back(planSweep(atMeasuredSize(input.scene, options), knobs));
        // the reference, the planned settings, and up to two tuned ones
        sweep.progress.settingsTotal += 3 + static_cast<int>(plans.back().settings.size());
    }
    sweep.progress.scenesTotal = static_cast<int>(scenes.size());

    for (size_t i = 0; i < scenes.size() && !result.cancelled; ++i) {
        const SweepPlan& plan = plans[i];
        SceneResult& sr = result.scenes.emplace_back();
        sr.name = scenes[i].name;
        sr.scene = plan.settings.front().scene;
        sr.notSwept = plan.notSwept;
        ReferenceOptions referenceOptions = options.reference;
        referenceOptions.minimumAa = std::max(referenceOptions.minimumAa, largestAa(plan));
        sr.reference = referenceScene(sr.scene, referenceOptions);

        auto skipRest = [&](size_t from) {
            result.budgetExhausted = true;
            for (size_t k = from; k < plan.settings.size(); ++k) {
                sr.skipped.push_back(plan.settings[k].label);
                sweep.advance(sr.name + ": " + plan.settings[k].label, false);
            }
        };
        if (sweep.outOfTime()) {
            sr.skipped.push_back("reference");
            sweep.advance(sr.name + ": reference", false);
            skipRest(0);
            ++sweep.progress.scenesDone;
            continue;
        }
        sweep.report(sr.name + ": reference");
        std::optional<ReferenceFrame> reference = obtainReference(sr.reference, options.cacheDir, options.cancel);
        if (!reference) {
            result.cancelled = true;
            break;
        }
        sr.referenceCached = reference->fromCache;
        sr.referenceSeconds = reference->seconds;
        sweep.advance(sr.name + ": reference", !reference->fromCache);

        // the shader build is not part of any timed render, nor is what a
        // backend does only the first time it renders a scene (first-touch
        // allocations, the GL program's first draw): an untimed render of the
        // default first (without it the default, measured first, took up to
        // 1.4 times as long as settings that give the same image)
        program::Program structure = program::compileScene(sr.scene);
        for (render::Backend* backend : backends) {
            backend->prepare(structure);
            if (!result.cancelled && !timedRender(*backend, structure, options.cancel)) result.cancelled = true;
        }
        if (result.cancelled) break;

        image::Frame defaultFrame;
        const Knob* inertKnob = nullptr;  // the knob whose cheapest value changed nothing
        for (size_t k = 0; k < plan.settings.size(); ++k) {
            const Setting& setting = plan.settings[k];
            if (setting.knob != nullptr && setting.knob == inertKnob) {
                sweep.advance(sr.name + ": " + setting.label, false);
                continue;
            }
            if (sweep.cancelled()) {
                result.cancelled = true;
                break;
            }
            if (sweep.outOfTime()) {
                skipRest(k);
                break;
            }
            sweep.report(sr.name + ": " + setting.label);
            auto measured = sweep.measure(setting, reference->frame);
            if (!measured) {
                result.cancelled = true;
                break;
            }
            bool firstOfKnob = setting.knob != nullptr && (k == 0 || plan.settings[k - 1].knob != setting.knob);
            if (k == 0) {
                defaultFrame = measured->second;
            } else if (firstOfKnob && sameImage(measured->second, defaultFrame)) {
                inertKnob = setting.knob;
                sr.notSwept.push_back({std::string(setting.knob->name),
                                       "image unchanged at " + setting.label.substr(setting.label.find('=') + 1)});
            }
            sr.results.push_back(std::move(measured->first));
            sweep.advance(sr.name + ": " + setting.label, true);
        }
        for (int extra = 0; extra < 2 && !result.cancelled; ++extra) {
            std::optional<Setting> setting = extra == 0 ? tuned(sr, options)
                                                        : (sr.results.back().setting.label.rfind("tuned:", 0) == 0
                                                               ? withoutRelaxation(sr.scene, sr.results.back().setting)
                                                               : std::nullopt);
            if (!setting || sr.results.empty()) {
                sweep.advance(sr.name + ": tuned", false);
                continue;
            }
            if (sweep.cancelled() || sweep.outOfTime()) {
                result.cancelled = sweep.cancelled();
                result.budgetExhausted = result.budgetExhausted || !result.cancelled;
                if (!result.cancelled) sr.skipped.push_back(setting->label);
                sweep.advance(sr.name + ": " + setting->label, false);
                continue;
            }
            sweep.report(sr.name + ": " + setting->label);
            auto measured = sweep.measure(*setting, reference->frame);
            if (!measured) {
                result.cancelled = true;
                break;
            }
            sr.results.push_back(std::move(measured->first));
            sweep.advance(sr.name + ": " + setting->label, true);
        }
        if (!result.cancelled && !sr.results.empty()) {
            storeMeasurements(options.cacheDir, measurementKey(scenes[i].scene), measurementsOf(sr, result.backends));
        }
        ++sweep.progress.scenesDone;
    }
    result.seconds = sweep.elapsed();
    return result;
}

}  // namespace sdfwb::tradeoff
