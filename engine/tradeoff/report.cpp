#include "tradeoff/report.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>

#include "tradeoff/analysis.h"
#include "tradeoff/knobs.h"

namespace sdfwb::tradeoff {
namespace {

std::string format(const char* pattern, double value) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, pattern, value);
    return buffer;
}

std::string milliseconds(double seconds) { return format("%.1f", seconds * 1000.0); }

// How many times faster `to` ran than `from` (0 when `to` took no time).
double speedup(const Measurement& from, const Measurement& to) {
    return to.seconds > 0 ? from.seconds / to.seconds : 0;
}

std::string describeSettings(const scene::Scene& s) {
    const scene::RenderSettings& r = s.render;
    std::ostringstream out;
    out << "AA " << r.aa << ", epsilon " << r.epsilon << (r.epsilonMode == scene::EpsilonMode::Pixel ? " px" : "")
        << ", max steps " << r.maxSteps << ", max distance " << r.maxDistance << ", shadow steps " << r.shadowSteps
        << ", AO samples " << r.aoSamples;
    return out.str();
}

double medianOf(std::vector<double> v) {
    if (v.empty()) return 0;
    std::sort(v.begin(), v.end());
    size_t n = v.size();
    return n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

constexpr const char* kRowHeader =
    "| setting | backend | ms | x default | mean steps | max steps | mean evals | "
    "mean err | max err | PSNR dB | % > 1/255 | % > 8/255 | hit mismatch % | depth err % | |\n"
    "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";

std::string row(const SceneResult& scene, size_t index, size_t backend, const std::string& backendName,
                const BackendAnalysis& a) {
    const Measurement& m = scene.results[index].byBackend[backend];
    const Measurement& d = scene.results[0].byBackend[backend];
    const image::Comparison& c = m.error.display;
    std::vector<std::string> marks;
    if (index == 0) marks.push_back("default");
    if (std::find(a.front.begin(), a.front.end(), index) != a.front.end()) marks.push_back("front");
    if (a.withinTolerance == index) marks.push_back("cheapest within 1/255");
    std::string markText;
    for (const std::string& mark : marks) markText += (markText.empty() ? "" : ", ") + mark;
    std::ostringstream out;
    out << "| " << scene.results[index].setting.label << " | " << backendName << " | " << milliseconds(m.seconds)
        << " | " << format("%.2f", speedup(d, m)) << " | " << format("%.1f", m.meanSteps) << " | "
        << format("%.0f", m.maxSteps) << " | " << format("%.1f", m.meanEvaluations) << " | "
        << format("%.3f", c.meanAbs) << " | " << format("%.0f", c.maxAbs) << " | "
        << (std::isinf(c.psnr) ? std::string("inf") : format("%.1f", c.psnr)) << " | "
        << format("%.2f", c.percentAbove1) << " | " << format("%.2f", c.percentAbove8) << " | "
        << format("%.3f", 100.0 * m.error.hitMismatch) << " | " << format("%.3f", 100.0 * m.error.depthError) << " | "
        << markText << " |\n";
    return out.str();
}

void writeScene(std::ostringstream& out, const SweepResult& result, const SceneResult& scene,
                const ReportContext& context) {
    out << "## " << scene.name << "\n\n";
    out << "Default: " << describeSettings(scene.scene) << ".  \n";
    out << "Reference: double-precision CPU, " << describeSettings(scene.reference) << " ("
        << (scene.referenceCached ? std::string("cached") : format("rendered in %.1f s", scene.referenceSeconds))
        << ").\n\n";
    for (const SkippedKnob& k : scene.notSwept) out << "- not swept: `" << k.knob << "` (" << k.reason << ")\n";
    if (!scene.skipped.empty()) {
        out << "- skipped for the budget: ";
        for (size_t i = 0; i < scene.skipped.size(); ++i) out << (i ? ", " : "") << scene.skipped[i];
        out << "\n";
    }
    if (!scene.notSwept.empty() || !scene.skipped.empty()) out << "\n";
    if (scene.results.empty()) return;
    if (auto plot = context.plots.find(scene.name); plot != context.plots.end()) {
        out << "![time against error, " << scene.name << "](" << plot->second << ")\n\n";
    }
    out << "Pareto front, the default and the cheapest setting within 1/255:\n\n" << kRowHeader;
    std::vector<BackendAnalysis> analyses;
    for (size_t b = 0; b < result.backends.size(); ++b) analyses.push_back(analyse(scene, b));
    for (size_t b = 0; b < result.backends.size(); ++b) {
        const BackendAnalysis& a = analyses[b];
        std::vector<size_t> shown = a.front;
        shown.push_back(0);
        if (a.withinTolerance) shown.push_back(*a.withinTolerance);
        std::sort(shown.begin(), shown.end(), [&](size_t x, size_t y) { return a.points[x].cost < a.points[y].cost; });
        shown.erase(std::unique(shown.begin(), shown.end()), shown.end());
        for (size_t i : shown) out << row(scene, i, b, result.backends[b], a);
    }
    out << "\n<details><summary>all " << scene.results.size() << " settings</summary>\n\n" << kRowHeader;
    for (size_t i = 0; i < scene.results.size(); ++i) {
        for (size_t b = 0; b < result.backends.size(); ++b) out << row(scene, i, b, result.backends[b], analyses[b]);
    }
    out << "\n</details>\n\n";
}

struct BackendTotals {
    int measured = 0;  // scenes with a measured default
    int defaultOnFront = 0;
    int defaultWithin = 0;         // defaults within 1/255 of the reference
    std::vector<double> speedups;  // default time / cheapest-within-1/255 time
};

void writeSummary(std::ostringstream& out, const SweepResult& result) {
    std::ostringstream table;
    table << "| scene | backend | default ms | default mean err | default on front | cheapest within 1/255 | ms | "
             "speed-up |\n|---|---|---|---|---|---|---|---|\n";
    std::vector<BackendTotals> totals(result.backends.size());
    for (size_t b = 0; b < result.backends.size(); ++b) {
        for (const SceneResult& scene : result.scenes) {
            if (scene.results.empty()) continue;
            BackendAnalysis a = analyse(scene, b);
            const Measurement& d = scene.results[0].byBackend[b];
            BackendTotals& t = totals[b];
            ++t.measured;
            t.defaultOnFront += a.defaultOnFront ? 1 : 0;
            t.defaultWithin += d.error.display.meanAbs <= kErrorTolerance ? 1 : 0;
            table << "| " << scene.name << " | " << result.backends[b] << " | " << milliseconds(d.seconds) << " | "
                  << format("%.3f", d.error.display.meanAbs) << " | " << (a.defaultOnFront ? "yes" : "no") << " | ";
            if (!a.withinTolerance) {
                table << "none | | |\n";
                continue;
            }
            const Measurement& c = scene.results[*a.withinTolerance].byBackend[b];
            double ratio = speedup(d, c);
            t.speedups.push_back(ratio);
            table << scene.results[*a.withinTolerance].setting.label << " | " << milliseconds(c.seconds) << " | "
                  << format("%.2f", ratio) << " |\n";
        }
    }
    out << "## Summary\n\n";
    for (size_t b = 0; b < result.backends.size(); ++b) {
        const BackendTotals& t = totals[b];
        out << "- " << result.backends[b] << ": " << t.measured << " scenes measured; the default is on the front in "
            << t.defaultOnFront << ", within 1/255 mean error of the reference in " << t.defaultWithin
            << "; a setting within 1/255 exists in " << t.speedups.size() << ", and the cheapest such is a median "
            << format("%.2f", medianOf(t.speedups)) << "x faster than the default.\n";
    }
    out << "\n" << table.str() << "\n";
}

// Of the results matching `wanted`, the one with the fewest mean steps whose
// error is within kErrorTolerance of result `plain`'s.
std::optional<size_t> fewestStepsAtEqualError(const SceneResult& scene, size_t backend, size_t plain,
                                              bool (*wanted)(const SettingResult&)) {
    double limit = scene.results[plain].byBackend[backend].error.display.meanAbs + kErrorTolerance;
    std::optional<size_t> best;
    for (size_t i = 0; i < scene.results.size(); ++i) {
        const Measurement& m = scene.results[i].byBackend[backend];
        if (!wanted(scene.results[i]) || m.error.display.meanAbs > limit) continue;
        if (!best || m.meanSteps < scene.results[*best].byBackend[backend].meanSteps) best = i;
    }
    return best;
}

bool isDefault(const SettingResult& r) { return r.setting.label == "default"; }
bool relaxedAlone(const SettingResult& r) {
    return r.setting.knob != nullptr && r.setting.knob->name == "step_relaxation";
}
bool relaxedTuned(const SettingResult& r) {
    return r.setting.label.rfind("tuned:", 0) == 0 && r.setting.scene.render.stepRelaxation > 1.0;
}

// Plain sphere tracing: the default with tracing=plain when that knob was
// swept, the default itself when the scene is plain already or the knob
// changes nothing in it (no ground, no bounds).
std::optional<size_t> plainSphereTracing(const SceneResult& scene) {
    const scene::Scene& s = scene.scene;
    if (s.render.stepRelaxation != 1.0) return std::nullopt;
    if (s.render.tracing == scene::Tracing::Plain) return 0;
    for (size_t i = 0; i < scene.results.size(); ++i) {
        const Setting& setting = scene.results[i].setting;
        if (setting.knob != nullptr && setting.knob->name == "tracing") return i;
    }
    const Knob* tracing = findKnob("tracing");
    if (tracing != nullptr && !tracing->inert(s).empty()) return 0;
    return std::nullopt;
}

void writeSpeedup(std::ostringstream& out, const SweepResult& result) {
    std::ostringstream table;
    table << "| scene | backend | plain: steps | evals | ms | err | default | steps | evals | ms | err | "
             "default, relaxed | steps | evals | ms | err | tuned, relaxed | steps | evals | ms | err |\n"
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    struct Ratios {
        std::vector<double> steps, evaluations, time;
    };
    enum { kDefault, kAlone, kTuned, kKinds };
    std::vector<std::array<Ratios, kKinds>> ratios(result.backends.size());
    auto cells = [](const Measurement& m) {
        return format("%.1f", m.meanSteps) + " | " + format("%.1f", m.meanEvaluations) + " | " +
               milliseconds(m.seconds) + " | " + format("%.3f", m.error.display.meanAbs);
    };
    auto ratio = [](double plain, double other) { return other > 0 ? plain / other : 0.0; };
    bool any = false;
    for (size_t b = 0; b < result.backends.size(); ++b) {
        for (const SceneResult& scene : result.scenes) {
            if (scene.results.empty()) continue;
            std::optional<size_t> plainIndex = plainSphereTracing(scene);
            if (!plainIndex) continue;
            std::array<std::optional<size_t>, kKinds> faster = {
                *plainIndex == 0 ? std::nullopt : fewestStepsAtEqualError(scene, b, *plainIndex, isDefault),
                fewestStepsAtEqualError(scene, b, *plainIndex, relaxedAlone),
                fewestStepsAtEqualError(scene, b, *plainIndex, relaxedTuned)};
            if (!faster[kDefault] && !faster[kAlone] && !faster[kTuned]) continue;
            any = true;
            const Measurement& plain = scene.results[*plainIndex].byBackend[b];
            table << "| " << scene.name << " | " << result.backends[b] << " | " << cells(plain);
            for (int kind = 0; kind < kKinds; ++kind) {
                if (!faster[kind]) {
                    table << " | none | | | |";
                    continue;
                }
                const SettingResult& r = scene.results[*faster[kind]];
                const Measurement& m = r.byBackend[b];
                std::string label = r.setting.label;
                if (label.rfind("tuned:", 0) == 0) label = label.substr(7);
                table << " | " << label << " | " << cells(m);
                Ratios& into = ratios[b][static_cast<size_t>(kind)];
                into.steps.push_back(ratio(plain.meanSteps, m.meanSteps));
                into.evaluations.push_back(ratio(plain.meanEvaluations, m.meanEvaluations));
                into.time.push_back(speedup(plain, m));
            }
            table << " |\n";
        }
    }
    if (!any) return;
    out << "## Faster tracing against plain sphere tracing\n\n"
        << "Plain: the scene's default with `tracing=plain`, plain sphere tracing of the field alone (the ground "
           "plane traced as any surface, the march sampling its way past the scene, every shadow ray sampled to its "
           "end); the default itself in scenes where that knob changes nothing (scenes where it was not swept "
           "otherwise are left out). Default: the scene's default, `tracing` \"bounded\" (the ground plane met along "
           "the ray, empty space outside the scene's bounds crossed in one step, the floor far from them shaded "
           "as a plane, shadow rays ended by them), when its mean error is within 1/255 of the plain one's. "
           "Default, relaxed: the default with the `step_relaxation` value that has the fewest primary steps per "
           "sub-sample among those whose mean error is within 1/255 of the plain one's (both speed-ups together). "
           "Tuned, relaxed: the tuned setting (each knob's fastest value within the tuning slack, combined) when it "
           "relaxes steps, under the same error condition. Steps are the primary march's evaluations, evals all "
           "field evaluations (march, normal, material, AO, shadows), per sub-sample. Ratios are plain over faster, "
           "medians over the scenes that have such a setting.\n\n";
    const char* names[kKinds] = {"default (bounded tracing)", "default, relaxed", "tuned and relaxed"};
    for (size_t b = 0; b < result.backends.size(); ++b) {
        out << "- " << result.backends[b] << ":";
        for (int kind = 0; kind < kKinds; ++kind) {
            const Ratios& r = ratios[b][static_cast<size_t>(kind)];
            out << (kind == 0 ? " " : "; ") << names[kind];
            if (r.steps.empty()) {
                out << ": no scene";  // a median of nothing is no ratio
                continue;
            }
            out << " (" << r.steps.size() << " scenes): " << format("%.2f", medianOf(r.steps)) << "x fewer steps, "
                << format("%.2f", medianOf(r.evaluations)) << "x fewer evaluations, "
                << format("%.2f", medianOf(r.time)) << "x faster";
        }
        out << ".\n";
    }
    out << "\n" << table.str() << "\n";
}

void writeSuggestedDefaults(std::ostringstream& out, const SweepResult& result) {
    std::ostringstream table;
    table << "| scene | suggested default |";
    for (const std::string& backend : result.backends) table << " " << backend << " speed-up | " << backend << " err |";
    table << "\n|---|---|";
    for (size_t b = 0; b < result.backends.size(); ++b) table << "---|---|";
    table << "\n";
    int suggested = 0, measured = 0;
    for (const SceneResult& scene : result.scenes) {
        if (scene.results.empty()) continue;
        ++measured;
        std::optional<size_t> index = suggestedDefault(scene);
        if (!index) continue;
        ++suggested;
        table << "| " << scene.name << " | " << scene.results[*index].setting.label << " |";
        for (size_t b = 0; b < result.backends.size(); ++b) {
            const Measurement& m = scene.results[*index].byBackend[b];
            table << " " << format("%.2f", speedup(scene.results[0].byBackend[b], m)) << " | "
                  << format("%.3f", m.error.display.meanAbs) << " |";
        }
        table << "\n";
    }
    out << "## Defaults the measurements suggest\n\n"
        << "A setting at least " << format("%.1f", kDefaultChangeSpeedup)
        << "x faster than the scene's default on every backend and no further from the reference than the default "
           "or 1/255, whichever is more (the cheapest such; docs/scene-defaults.md says which scenes take it): "
        << suggested << " of " << measured << " scenes.\n\n";
    if (suggested > 0) out << table.str() << "\n";
}

void writeSkipped(std::ostringstream& out, const SweepResult& result) {
    if (!result.budgetExhausted) return;
    out << "**The budget ran out**: ";
    int settings = 0, scenes = 0;
    for (const SceneResult& scene : result.scenes) {
        settings += static_cast<int>(scene.skipped.size());
        scenes += scene.results.empty() ? 1 : 0;
    }
    out << settings << " settings were not measured (" << scenes
        << " scenes not at all); each scene below lists what it skipped.\n\n";
}

}  // namespace

std::string writeReport(const SweepResult& result, const ReportContext& context) {
    std::ostringstream out;
    out << "# Speed against error\n\n";
    if (!context.command.empty()) out << "Made by `" << context.command << "`";
    out << " in " << format("%.0f", result.seconds) << " s";
    if (!context.machine.empty()) out << ", " << context.machine;
    out << ".\n\n"
        << "Time is the median of the repetitions of each render (backends interleaved, shader builds and an untimed "
           "first render of each scene excluded). "
           "Errors are against the reference (double-precision CPU, tight settings), on the 8-bit display encoding "
           "as `compare` prints them; hit mismatch is the share of sub-samples that hit in one image only, depth "
           "error the mean relative difference of the march distance where both hit everywhere in the pixel. "
           "Steps are primary-march evaluations per sub-sample. A setting is on the Pareto front when no other is "
           "both faster and closer to the reference; each knob is varied alone around the scene's default.\n\n";
    writeSkipped(out, result);
    writeSummary(out, result);
    writeSuggestedDefaults(out, result);
    writeSpeedup(out, result);
    for (const SceneResult& scene : result.scenes) writeScene(out, result, scene, context);
    return out.str();
}

}  // namespace sdfwb::tradeoff
