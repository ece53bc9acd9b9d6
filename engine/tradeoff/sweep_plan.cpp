#include "tradeoff/sweep_plan.h"

#include <algorithm>
#include <stdexcept>

#include "scene/scene_json.h"

namespace sdfwb::tradeoff {
namespace {

std::vector<std::string> split(const std::string& text, char separator) {
    std::vector<std::string> parts;
    size_t start = 0;
    while (true) {
        size_t end = text.find(separator, start);
        parts.push_back(text.substr(start, end - start));
        if (end == std::string::npos) return parts;
        start = end + 1;
    }
}

std::string knownKnobs() {
    std::string list;
    for (const Knob& knob : knobs()) list += (list.empty() ? "" : ", ") + std::string(knob.name);
    return list;
}

// The scene format's own validation, so that ranges stay defined once.
std::string rejection(const scene::Scene& s) {
    try {
        scene::sceneFromJson(scene::sceneToJson(s));
        return "";
    } catch (const scene::SceneError& error) {
        return error.problems().empty() ? "invalid" : error.problems().front();
    }
}

}  // namespace

std::vector<KnobRequest> parseKnobRequests(const std::vector<std::string>& specs) {
    std::vector<KnobRequest> requests;
    for (const std::string& spec : specs) {
        size_t equals = spec.find('=');
        std::string name = spec.substr(0, equals);
        const Knob* knob = findKnob(name);
        if (knob == nullptr) {
            throw std::invalid_argument("--knobs: unknown knob '" + name + "' (known: " + knownKnobs() + ")");
        }
        for (const KnobRequest& r : requests) {
            if (r.knob == knob) throw std::invalid_argument("--knobs: '" + name + "' given twice");
        }
        KnobRequest request{knob, {}};
        if (equals != std::string::npos) {
            for (const std::string& text : split(spec.substr(equals + 1), ',')) {
                try {
                    request.values.push_back(parseKnobValue(*knob, text));
                } catch (const std::invalid_argument& error) {
                    throw std::invalid_argument(std::string("--knobs: ") + error.what());
                }
            }
        }
        requests.push_back(std::move(request));
    }
    if (requests.empty()) {
        for (const Knob& knob : knobs()) requests.push_back({&knob, {}});
    }
    return requests;
}

SweepPlan planSweep(const scene::Scene& base, const std::vector<KnobRequest>& requests) {
    SweepPlan plan;
    plan.settings.push_back({nullptr, 0, "default", base});
    for (const KnobRequest& request : requests) {
        const Knob& knob = *request.knob;
        if (std::string reason = knob.inert(base); !reason.empty()) {
            plan.notSwept.push_back({std::string(knob.name), reason});
            continue;
        }
        bool given = !request.values.empty();
        std::vector<double> values = given ? request.values : knob.defaults(base);
        double own = knob.get(base);
        for (double value : values) {
            if (value == own) continue;  // that is the default setting
            Setting setting{&knob, value, std::string(knob.name) + "=" + formatKnobValue(knob, value), base};
            knob.set(setting.scene, value);
            if (std::string problem = rejection(setting.scene); !problem.empty()) {
                if (given) throw std::invalid_argument("--knobs: " + setting.label + ": " + problem);
                continue;
            }
            plan.settings.push_back(std::move(setting));
        }
    }
    return plan;
}

std::optional<Setting> tunedSetting(const scene::Scene& base, const std::vector<TuningCandidate>& candidates,
                                    double defaultSeconds, double defaultError, double slack) {
    std::vector<const TuningCandidate*> chosen;  // one per knob, in the order the knobs come
    for (const TuningCandidate& c : candidates) {
        if (c.setting->knob == nullptr || c.error > defaultError + slack || !(c.seconds < defaultSeconds)) continue;
        auto same = std::find_if(chosen.begin(), chosen.end(),
                                 [&](const TuningCandidate* o) { return o->setting->knob == c.setting->knob; });
        if (same == chosen.end()) {
            chosen.push_back(&c);
        } else if (c.seconds < (*same)->seconds) {
            *same = &c;
        }
    }
    if (chosen.empty()) return std::nullopt;
    Setting tuned{nullptr, 0, "tuned:", base};
    for (const TuningCandidate* c : chosen) {
        c->setting->knob->set(tuned.scene, c->setting->value);
        tuned.label += " " + c->setting->label;
    }
    return tuned;
}

std::optional<Setting> withoutRelaxation(const scene::Scene& base, const Setting& tuned) {
    if (tuned.scene.render.stepRelaxation == base.render.stepRelaxation) return std::nullopt;
    Setting plain = tuned;
    plain.scene.render.stepRelaxation = base.render.stepRelaxation;
    plain.label = "tuned, plain steps:" + tuned.label.substr(tuned.label.find(':') + 1);
    std::string relaxed = " step_relaxation=";
    size_t at = plain.label.find(relaxed);
    if (at != std::string::npos) plain.label.erase(at, plain.label.find(' ', at + 1) - at);
    if (plain.scene == base) return std::nullopt;  // relaxation was all the tuning: that is the default
    return plain;
}

}  // namespace sdfwb::tradeoff
