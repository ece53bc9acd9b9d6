#pragma once
// The polynomial panel's background work, apart from its widgets: implicitize
// parametric equations as a background job (jobs/job_queue.h) under a Budget
// (cancel flag, time and memory limits), publish its progress for the UI
// thread to read each frame, read the equations' parameters off the UI
// thread, and turn the result into a `polynomial` scene node.

#include <chrono>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "algebra/budget.h"
#include "algebra/implicitization.h"
#include "expr/trig.h"
#include "jobs/job_queue.h"
#include "scene/scene.h"

namespace sdfwb::ui {

// A parameter of the equations and the interval the user gives it.
struct ParameterRange {
    std::string name;
    double min = -1, max = 1;
    bool angle = false;  // used inside sin, cos or tan
    friend bool operator==(const ParameterRange&, const ParameterRange&) = default;
};

struct PolynomialRequest {
    std::string equations = "x = u*v; y = v; z = u^2";
    expr::TrigStrategy trig = expr::TrigStrategy::CosSinRelation;
    algebra::EliminationOrder order = algebra::EliminationOrder::BlockDegrevlex;
    // When given, the node's bounds are the sampled image of this box (every
    // parameter must be listed); when empty, the node's defaults.
    std::vector<ParameterRange> parameterRanges;
    double timeLimitSeconds = 60;  // s
};

struct PolynomialOutcome {
    bool ok = false;
    // ok: a summary ("degree 3, 4 terms, 0.002 s"); else the parse error or
    // "gave up after ..." / "cancelled after ..." message, one line.
    std::string message;
    // The generators as the formula language reads them (Polynomial::toString).
    std::vector<std::string> generators;
    std::uint64_t degree = 0;  // the largest total degree
    std::size_t terms = 0;     // summed over the generators
    double seconds = 0;
    // The sampled image of the parameter box, padded; absent without a range.
    std::optional<std::pair<glm::dvec3, glm::dvec3>> bounds;

    // Exactly one generator: a surface F = 0 a polynomial node can show.
    bool isSurface() const { return ok && generators.size() == 1; }
};

// A snapshot of a running job, safe to read from the UI thread.
struct PolynomialProgress {
    double elapsedSeconds = 0;  // since start(), live while running
    std::size_t basisSize = 0;
    std::size_t pairsLeft = 0;
    std::string stage;  // "buchberger", "interpolation (3 primes)", ...
};

// One computation at a time: a new start() cancels the running one and
// supersedes it (its result is dropped). The worker never touches the scene:
// the UI thread polls outcome() and adds the node through the Editor itself.
class PolynomialJob {
public:
    PolynomialJob() = default;
    PolynomialJob(const PolynomialJob&) = delete;
    PolynomialJob& operator=(const PolynomialJob&) = delete;
    // Cancels a running computation and waits for it (it stops at the
    // engine's next safe point).
    ~PolynomialJob();

    // Starts `request`, cancelling a running one; never waits.
    void start(PolynomialRequest request);
    // Asks the worker to stop; outcome() then reports "cancelled".
    void cancel();
    bool running() const;
    PolynomialProgress progress() const;
    // The last finished computation's result (nullopt while none finished).
    std::optional<PolynomialOutcome> outcome() const;
    // Waits for the computation (tests and scripts; the UI polls instead).
    void wait() const;

private:
    struct Shared {
        mutable std::mutex mutex;
        std::chrono::steady_clock::time_point started;
        PolynomialProgress progress;
        std::optional<PolynomialOutcome> outcome;
    };
    std::shared_ptr<Shared> shared_ = std::make_shared<Shared>();
    std::shared_ptr<algebra::CancelToken> cancel_;
    jobs::JobHandle job_;
    jobs::JobQueue queue_{1};  // last: stops before the rest goes
};

// The parameters of equations (parameterRanges), read off the UI thread:
// reading converts the equations, which can expand large powers. A newer
// text supersedes one still queued; the UI applies the newest result when
// it is ready.
class ParameterCheck {
public:
    struct Result {
        std::string equations;               // the text checked
        std::vector<ParameterRange> ranges;  // when `problem` is ""
        std::string problem;                 // why the equations cannot run, with a column
    };
    // Checks `equations` (keeping `previous` ranges, as parameterRanges
    // does) unless they are the text last requested.
    void request(const std::string& equations, std::vector<ParameterRange> previous);
    // The newest request's result, once, when it is ready.
    std::optional<Result> take();
    // A request's result is not taken yet.
    bool pending() const { return job_ != nullptr; }
    // Waits for the newest request (scripts and tests; the UI polls).
    void wait() const;

private:
    std::optional<std::string> requested_;
    jobs::JobHandle job_;
    std::shared_ptr<Result> result_;  // written by the job
    jobs::JobQueue queue_{1};         // last: stops before the rest goes
};

// Runs a request on the calling thread (the worker's body).
PolynomialOutcome computePolynomial(const PolynomialRequest& request, const algebra::Budget& budget);

// The parameters of `equations` in order of first use, each with its range
// from `previous` when listed there with the same role (angle or not), else
// one whole period for an angle ([0, 2π] for cos(u), [0, 4π] for cos(u/2))
// and [-1, 1] for any other. Throws what Run would
// report for equations that cannot be implicitized (expr::Error with a column).
std::vector<ParameterRange> parameterRanges(std::string_view equations, std::span<const ParameterRange> previous = {});

// The image of the parameter box under the equations, sampled on a grid and
// padded by 5% (at least 0.05) per axis; nullopt when no sample is finite.
// Throws std::invalid_argument naming a parameter missing from `ranges`.
std::optional<std::pair<glm::dvec3, glm::dvec3>> sampledBounds(std::string_view equations,
                                                               std::span<const ParameterRange> ranges);

// A `polynomial` node named "polynomial" with the outcome's generator as its
// formula, its bounds when sampled, and the sheet thickness (0: the solid
// F <= 0). Requires outcome.isSurface().
scene::Node polynomialNode(const PolynomialOutcome& outcome, double sheetThickness = 0);

}  // namespace sdfwb::ui
