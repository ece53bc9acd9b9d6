#include "ui/polynomial_job.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <vector>

#include <glm/common.hpp>

#include "algebra/implicitization.h"
#include "expr/formula.h"
#include "expr/tape.h"
#include "expr/trig.h"

namespace sdfwb::ui {
namespace {

// Keeps a runaway computation from exhausting the machine (as the CLI does).
constexpr std::size_t kMemoryLimitBytes = std::size_t(8) << 30;

std::string summary(const PolynomialOutcome& o) {
    char text[160];
    std::snprintf(text, sizeof text, "degree %llu, %zu term%s, %.3f s", static_cast<unsigned long long>(o.degree),
                  o.terms, o.terms == 1 ? "" : "s", o.seconds);
    std::string line = text;
    if (o.generators.size() > 1) {
        line += ", " + std::to_string(o.generators.size()) + " generators (a curve: all of them vanish on it)";
    }
    if (o.generators.empty()) line += ", no equation: the image is dense";
    return line;
}

}  // namespace

PolynomialOutcome computePolynomial(const PolynomialRequest& request, const algebra::Budget& budget) {
    PolynomialOutcome out;
    try {
        expr::TrigConversion conversion = expr::parseParametrization(request.equations, request.trig);
        algebra::ImplicitizationOptions options;
        options.groebner.budget = budget;
        options.order = request.order;
        algebra::ImplicitizationResult result = algebra::implicitize(conversion.parametrization, options);
        out.seconds = result.seconds;
        if (!result.ok()) {
            out.message = result.message.empty() ? algebra::toString(result.status) : result.message;
            return out;
        }
        out.degree = result.degree();
        out.terms = result.termCount();
        for (const algebra::Polynomial& g : result.generators) out.generators.push_back(g.toString());
        if (!request.parameterRanges.empty()) out.bounds = sampledBounds(request.equations, request.parameterRanges);
        out.ok = true;
        out.message = summary(out);
    } catch (const std::exception& error) {
        out.message = error.what();
    }
    return out;
}

std::vector<ParameterRange> parameterRanges(std::string_view equations, std::span<const ParameterRange> previous) {
    expr::ParametricEquations parsed = expr::compileParametricEquations(equations);
    // the conversion finds the angles, and refuses what Run would refuse
    expr::TrigConversion conversion = expr::toRationalParametrization(parsed, expr::TrigStrategy::CosSinRelation);
    std::vector<ParameterRange> ranges;
    for (const std::string& name : parsed.graph.variables()) {
        auto angle = std::find_if(conversion.angles.begin(), conversion.angles.end(),
                                  [&](const expr::AngleSubstitution& a) { return a.parameter == name; });
        bool isAngle = angle != conversion.angles.end();
        auto kept = std::find_if(previous.begin(), previous.end(),
                                 [&](const ParameterRange& r) { return r.name == name && r.angle == isAngle; });
        if (kept != previous.end()) {
            ranges.push_back(*kept);
        } else if (isAngle) {
            // parameter = scale * psi with psi a full turn: one whole period
            ranges.push_back({name, 0, 2 * std::numbers::pi * std::abs(angle->scale.get_d()), true});
        } else {
            ranges.push_back({name});
        }
    }
    return ranges;
}

std::optional<std::pair<glm::dvec3, glm::dvec3>> sampledBounds(std::string_view equations,
                                                               std::span<const ParameterRange> ranges) {
    expr::ParametricEquations parsed = expr::compileParametricEquations(equations);
    std::vector<expr::NodeId> outputs;
    std::vector<int> axis;
    for (const expr::CoordinateEquation& e : parsed.equations) {
        outputs.push_back(e.value);
        axis.push_back(e.coordinate[0] - 'x');
    }
    expr::Tape tape(parsed.graph, outputs);
    expr::Evaluator<double> evaluate(tape);
    const std::size_t parameters = tape.variables().size();
    std::vector<ParameterRange> box;  // in the tape's order
    for (const std::string& name : tape.variables()) {
        auto range = std::find_if(ranges.begin(), ranges.end(), [&](const ParameterRange& r) { return r.name == name; });
        if (range == ranges.end()) throw std::invalid_argument("no range for the parameter '" + name + "'");
        box.push_back(*range);
    }
    // 33 samples per parameter for curves and surfaces, fewer beyond
    const int steps = parameters <= 2 ? 32 : 12;
    std::size_t count = 1;
    for (std::size_t i = 0; i < parameters; ++i) count *= steps + 1;
    glm::dvec3 low(std::numeric_limits<double>::infinity()), high(-std::numeric_limits<double>::infinity());
    std::vector<double> values(parameters);
    bool any = false;
    for (std::size_t index = 0; index < count; ++index) {
        std::size_t rest = index;
        for (std::size_t i = 0; i < parameters; ++i) {
            values[i] = box[i].min + (box[i].max - box[i].min) * static_cast<double>(rest % (steps + 1)) / steps;
            rest /= steps + 1;
        }
        std::span<const double> point = evaluate(values);
        glm::dvec3 p(0.0);  // a coordinate without an equation stays 0
        bool finite = true;
        for (std::size_t k = 0; k < point.size(); ++k) {
            finite = finite && std::isfinite(point[k]);
            p[axis[k]] = point[k];
        }
        if (!finite) continue;
        low = glm::min(low, p);
        high = glm::max(high, p);
        any = true;
    }
    if (!any) return std::nullopt;
    for (int k = 0; k < 3; ++k) {
        // a flat direction (a plane, a curve) still needs a box with volume
        double pad = std::max(0.05 * (high[k] - low[k]), 0.05);
        low[k] -= pad;
        high[k] += pad;
    }
    return std::pair{low, high};
}

scene::Node polynomialNode(const PolynomialOutcome& outcome, double sheetThickness) {
    scene::Node node = scene::Node::make(scene::NodeKind::Polynomial);
    node.name = "polynomial";
    node.set("formula", outcome.generators.at(0));
    node.set("sheet_thickness", sheetThickness);
    if (outcome.bounds) {
        node.set("bounds_min", outcome.bounds->first);
        node.set("bounds_max", outcome.bounds->second);
    }
    return node;
}

PolynomialJob::~PolynomialJob() { cancel(); }

void PolynomialJob::start(PolynomialRequest request) {
    cancel();
    cancel_ = std::make_shared<algebra::CancelToken>();
    shared_ = std::make_shared<Shared>();  // a superseded job keeps writing into its own
    shared_->started = std::chrono::steady_clock::now();
    algebra::Budget budget;
    budget.timeLimitSeconds = request.timeLimitSeconds;
    budget.memoryLimitBytes = kMemoryLimitBytes;
    budget.cancel = cancel_;
    budget.progressIntervalSeconds = 0.1;
    std::shared_ptr<Shared> shared = shared_;
    budget.onProgress = [shared](const algebra::Progress& p) {
        std::lock_guard lock(shared->mutex);
        // the modular stages (interpolation, lifting, verification) count
        // primes, which the panel shows with the stage
        std::string stage = p.stage;
        if (p.primes > 0) stage += " (" + std::to_string(p.primes) + (p.primes == 1 ? " prime)" : " primes)");
        shared->progress = {p.elapsedSeconds, p.basisSize, p.pairsLeft, std::move(stage)};
    };
    job_ = queue_.submit([shared, request = std::move(request), budget = std::move(budget)](jobs::Job&) {
        PolynomialOutcome outcome = computePolynomial(request, budget);
        std::lock_guard lock(shared->mutex);
        shared->outcome = std::move(outcome);
    });
}

void PolynomialJob::cancel() {
    if (cancel_) cancel_->cancel();
}

bool PolynomialJob::running() const { return job_ && !job_->finished(); }

PolynomialProgress PolynomialJob::progress() const {
    std::lock_guard lock(shared_->mutex);
    PolynomialProgress now = shared_->progress;
    // the engine reports every 0.1 s at best; the clock keeps moving between
    if (running()) {
        now.elapsedSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - shared_->started).count();
    }
    return now;
}

std::optional<PolynomialOutcome> PolynomialJob::outcome() const {
    std::lock_guard lock(shared_->mutex);
    return shared_->outcome;
}

void PolynomialJob::wait() const {
    if (job_) job_->wait();
}

void ParameterCheck::request(const std::string& equations, std::vector<ParameterRange> previous) {
    if (requested_ == equations) return;
    requested_ = equations;
    queue_.cancelAll();  // an older text still queued is dropped
    result_ = std::make_shared<Result>();
    result_->equations = equations;
    job_ = queue_.submit([result = result_, previous = std::move(previous)](jobs::Job&) {
        try {
            result->ranges = parameterRanges(result->equations, previous);
        } catch (const std::exception& error) {
            result->problem = error.what();
        }
    });
}

std::optional<ParameterCheck::Result> ParameterCheck::take() {
    if (!job_ || !job_->finished()) return std::nullopt;
    job_.reset();
    return std::move(*result_);
}

void ParameterCheck::wait() const {
    if (job_) job_->wait();
}

}  // namespace sdfwb::ui
