#include "prune/cell_pruning.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

#include "cpu/interpreter.h"
#include "prune/prune_grid.h"
#include "sdf/shared.h"

namespace sdfwb::prune {

// The CPU interpreter in double: the analysis evaluates instructions at a
// cell's centre with the same shared functions the backends run.
namespace f64 = cpu::f64;

namespace {

using program::Instruction;
using program::Opcode;

constexpr double kInf = std::numeric_limits<double>::infinity();

struct Interval {
    double lo;
    double hi;
};

// Bounds over the cell of a sample register's two channels.
struct Range {
    Interval d;
    Interval step;
};

Range unknownRange() { return {{-kInf, kInf}, {-kInf, kInf}}; }
Range around(double d, double step, double radius) {
    return {{d - radius, d + radius}, {step - radius, step + radius}};
}
// The ground's safe step (groundSafeStep, instGround's) is non-decreasing in
// its distance, so its range is the step at the ends of the distance's.
Range groundRange(double d, double radius, bool alongRay) {
    Interval distance{d - radius, d + radius};
    return {distance,
            {sdf::f64::groundSafeStep(distance.lo, alongRay), sdf::f64::groundSafeStep(distance.hi, alongRay)}};
}
Range negated(const Range& r) { return {{-r.d.hi, -r.d.lo}, {-r.step.hi, -r.step.lo}}; }

// A point register over the cell: its value at the centre and how far from it
// the value can be anywhere in the cell.
struct PointBound {
    glm::dvec3 centre;
    double radius;
};

// What a boolean's result equals over the cell.
enum class Outcome { Both, OnlyA, OnlyB };

// Smooth variants whose result is bit-exactly the smaller operand once the
// operands are far enough apart, and how far (docs/large-scenes.md):
// polynomial has compact support k; the exponential's weight 2^(-4|a-b|/k)
// drops below 2^-56 at |a-b| >= 14k, where 1 + weight rounds to 1 in float and
// double; root never returns either operand exactly.
constexpr double kExponentialGapPerK = 14.0;
// power: (m/M)^(1/k) <= 2^-56 once M >= m * 2^(56 k)
constexpr double kPowerExponentPerK = 56.0;

// True when, in smoothMin(variant, x, y), the operand x never changes the
// result anywhere in the cell: the result is exactly y. `hard` for min itself.
bool neverMatters(const Interval& x, const Interval& y, bool hard, int variant, double k, double slack) {
    if (!hard && variant == sdf::f64::SMOOTH_ROOT) {
        return false;  // infinite support, never exactly either operand
    }
    if (hard || !(k > 0.0)) {
        return x.lo > y.hi + slack;
    }
    if (variant == sdf::f64::SMOOTH_POLYNOMIAL) {
        return x.lo > y.hi + k + slack;
    }
    if (variant == sdf::f64::SMOOTH_EXPONENTIAL) {
        return x.lo > y.hi + kExponentialGapPerK * k + slack;
    }
    if (variant == sdf::f64::SMOOTH_POWER) {
        // where y <= 0 the power minimum is the hard minimum
        return x.lo > slack && x.lo > std::max(y.hi, 0.0) * std::exp2(kPowerExponentPerK * k) + slack;
    }
    return false;
}

bool neverMatters(const Range& x, const Range& y, bool hard, int variant, double k, double slack) {
    return neverMatters(x.d, y.d, hard, variant, k, slack) && neverMatters(x.step, y.step, hard, variant, k, slack);
}

// The operators are non-decreasing in each operand, so the result's bounds are
// the operator applied to the operands' bounds. Every smooth minimum lies at
// or below the hard one, so without finite bounds it has no lower bound.
Interval minInterval(const Interval& a, const Interval& b, bool hard, int variant, double k, double n) {
    if (hard) return {std::min(a.lo, b.lo), std::min(a.hi, b.hi)};
    bool finiteLo = std::isfinite(a.lo) && std::isfinite(b.lo), finiteHi = std::isfinite(a.hi) && std::isfinite(b.hi);
    return {finiteLo ? sdf::f64::smoothMin(variant, a.lo, b.lo, k, n).d : -kInf,
            finiteHi ? sdf::f64::smoothMin(variant, a.hi, b.hi, k, n).d : std::min(a.hi, b.hi)};
}

Range minRange(const Range& a, const Range& b, bool hard, int variant, double k, double n) {
    return {minInterval(a.d, b.d, hard, variant, k, n), minInterval(a.step, b.step, hard, variant, k, n)};
}

// How far a point operator can move the transformed point within a ball of
// `radius` about `centre`; infinite where the operator is not continuous there.
double repeatRadius(double centre, double radius, double spacing, double count, bool limited) {
    if (spacing == 0.0) return radius;
    auto cellOf = [&](double x) {
        double c = std::floor(x / spacing + 0.5);
        return limited ? std::clamp(c, -count, count) : c;
    };
    double slackRadius = radius * 1.001 + std::abs(spacing) * 1e-6;
    return cellOf(centre - slackRadius) == cellOf(centre + slackRadius) ? radius : kInf;
}

double pointRadius(const Instruction& in, const PointBound& p, const glm::dvec4* q) {
    double r = p.radius;
    if (!std::isfinite(r)) return kInf;
    switch (in.op) {
    case Opcode::Translate:
    case Opcode::Rotate:
    case Opcode::Mirror:
    case Opcode::Elongate: return r;  // 1-Lipschitz
    case Opcode::Scale: return r / std::abs(q[0].x);
    case Opcode::Twist: {
        // rotation by k y about y: |J| <= 1 + |k| (distance from the axis)
        double axis = std::hypot(p.centre.x, p.centre.z) + r;
        return r * (1.0 + std::abs(q[0].x) * axis);
    }
    case Opcode::Bend: {
        double axis = std::hypot(p.centre.x, p.centre.y) + r;
        return r * (1.0 + std::abs(q[0].x) * axis);
    }
    case Opcode::Repeat: {
        double rx = repeatRadius(p.centre.x, r, q[0].x, q[1].x, true);
        double ry = repeatRadius(p.centre.y, r, q[0].y, q[1].y, true);
        double rz = repeatRadius(p.centre.z, r, q[0].z, q[1].z, true);
        return std::max(rx, std::max(ry, rz));
    }
    case Opcode::RepeatInfinite: {
        double rx = repeatRadius(p.centre.x, r, q[0].x, 0.0, false);
        double ry = repeatRadius(p.centre.y, r, q[0].y, 0.0, false);
        double rz = repeatRadius(p.centre.z, r, q[0].z, 0.0, false);
        return std::max(rx, std::max(ry, rz));
    }
    default: return kInf;
    }
}

// Lipschitz bound of a shape's distance in its own frame; infinite for the
// shapes that have none we can rely on (ellipsoid's outside bound, formulas).
double shapeLipschitz(Opcode op) {
    switch (op) {
    case Opcode::Sphere:
    case Opcode::Box:
    case Opcode::RoundBox:
    case Opcode::Plane:
    case Opcode::Torus:
    case Opcode::Cone:
    case Opcode::Cylinder:
    case Opcode::Capsule:
    case Opcode::Ground: return 1.0;
    case Opcode::Ellipsoid:
    case Opcode::SdfFormula:
    case Opcode::ImplicitFormula: return kInf;
    default: return kInf;
    }
}

enum class Role { Point, Shape, Combine, Post, Constant };

Role roleOf(Opcode op) {
    switch (op) {
    case Opcode::Translate:
    case Opcode::Rotate:
    case Opcode::Scale:
    case Opcode::Twist:
    case Opcode::Bend:
    case Opcode::Elongate:
    case Opcode::Mirror:
    case Opcode::Repeat:
    case Opcode::RepeatInfinite: return Role::Point;
    case Opcode::Sphere:
    case Opcode::Box:
    case Opcode::RoundBox:
    case Opcode::Plane:
    case Opcode::Torus:
    case Opcode::Cone:
    case Opcode::Ellipsoid:
    case Opcode::Cylinder:
    case Opcode::Capsule:
    case Opcode::Ground:
    case Opcode::SdfFormula:
    case Opcode::ImplicitFormula: return Role::Shape;
    case Opcode::Union:
    case Opcode::Intersection:
    case Opcode::Difference:
    case Opcode::SmoothUnion:
    case Opcode::SmoothIntersection:
    case Opcode::SmoothDifference: return Role::Combine;
    case Opcode::ScaleDistance:
    case Opcode::RoundDistance:
    case Opcode::Displace:
    case Opcode::StepScale:
    case Opcode::Texture:
    case Opcode::ImageTexture:
    case Opcode::TriplanarTexture:
    case Opcode::Bump: return Role::Post;
    case Opcode::Empty: return Role::Constant;
    }
    return Role::Constant;
}

// Rounding of the float evaluation against the double analysis, at the
// magnitudes involved (coordinates and distances of the cell).
double slackFor(double scale, const Range& a, const Range& b) {
    double magnitude = scale;
    for (double v : {a.d.lo, a.d.hi, b.d.lo, b.d.hi, a.step.lo, a.step.hi, b.step.lo, b.step.hi}) {
        // the ground's clear step (and an empty group's distance, as large)
        // mean no surface, not a magnitude the other operand is rounded at:
        // counted, they made the slack 1e5 and kept the ground in every cell
        if (std::isfinite(v) && std::abs(v) < sdf::f64::GROUND_CLEAR_STEP) magnitude = std::max(magnitude, std::abs(v));
    }
    return 1e-5 * (1.0 + magnitude);
}

// One boolean over the cell: what its result equals, and its bounds.
Outcome decide(const Instruction& in, const Range& a, const Range& b, const glm::dvec4* q, double scale,
               Range& result) {
    bool hard = in.op == Opcode::Union || in.op == Opcode::Intersection || in.op == Opcode::Difference;
    bool maxType = in.op == Opcode::Intersection || in.op == Opcode::SmoothIntersection ||
                   in.op == Opcode::Difference || in.op == Opcode::SmoothDifference;
    bool difference = in.op == Opcode::Difference || in.op == Opcode::SmoothDifference;
    double k = hard ? 0.0 : q[0].x, n = hard ? 2.0 : q[0].y;
    int variant = hard ? 0 : in.variant;
    // every boolean as a minimum: max(a, b) = -min(-a, -b), a difference's
    // second operand is -b
    Range x = maxType ? negated(a) : a;
    Range y = maxType ? (difference ? b : negated(b)) : b;
    double slack = slackFor(scale, x, y);
    Outcome outcome = Outcome::Both;
    if (neverMatters(y, x, hard, variant, k, slack)) {
        outcome = Outcome::OnlyA;
    } else if (!difference && neverMatters(x, y, hard, variant, k, slack)) {
        outcome = Outcome::OnlyB;  // a difference's -b is no plain copy of b
    }
    if (outcome == Outcome::OnlyA) {
        result = a;
    } else if (outcome == Outcome::OnlyB) {
        result = b;
    } else {
        Range m = minRange(x, y, hard, variant, k, n);
        result = maxType ? negated(m) : m;
    }
    return outcome;
}

Range postRange(const Instruction& in, const Range& s, const glm::dvec4* q) {
    switch (in.op) {
    case Opcode::ScaleDistance: {
        double f = q[0].x;
        auto scaled = [&](Interval i) { return f >= 0.0 ? Interval{i.lo * f, i.hi * f} : Interval{i.hi * f, i.lo * f}; };
        return {scaled(s.d), scaled(s.step)};
    }
    case Opcode::RoundDistance: return {{s.d.lo - q[0].x, s.d.hi - q[0].x}, {s.step.lo - q[0].x, s.step.hi - q[0].x}};
    case Opcode::Displace: {
        double amplitude = std::abs(q[0].x), f = q[0].z;
        return {{s.d.lo - amplitude, s.d.hi + amplitude}, {(s.step.lo - amplitude) * f, (s.step.hi + amplitude) * f}};
    }
    case Opcode::StepScale: return {s.d, {s.step.lo * q[0].x, s.step.hi * q[0].x}};
    case Opcode::Texture:
    case Opcode::ImageTexture:
    case Opcode::TriplanarTexture:
    case Opcode::Bump: return s;  // the material only
    default: return unknownRange();
    }
}

// Drops what the outcomes make dead and renames sample registers so that a
// boolean's surviving operand is written where the boolean's result was read.
// Returns false when a rename would overwrite a live value (never for
// compileScene's register stacks; then the cell keeps the full list).
bool rewrite(const program::Program& program, const CodeSpan& input, const std::vector<Outcome>& outcomes,
             CodeSpan& output) {
    const std::vector<Instruction>& code = input.code;
    std::vector<int> target(static_cast<size_t>(program.sampleRegisters), -1);  // live value -> register
    std::vector<int> owner(static_cast<size_t>(program.sampleRegisters), -1);   // register -> live value
    std::vector<char> pointLive(static_cast<size_t>(program.pointRegisters), 0);
    auto need = [&](int reg, int where) {
        size_t r = static_cast<size_t>(reg), w = static_cast<size_t>(where);
        if (target[r] != -1) return target[r] == where;
        if (owner[w] != -1) return false;
        target[r] = where;
        owner[w] = reg;
        return true;
    };
    auto define = [&](int reg) {
        size_t r = static_cast<size_t>(reg);
        int where = target[r];
        owner[static_cast<size_t>(where)] = -1;
        target[r] = -1;
        return where;
    };
    std::vector<Instruction> kept;
    need(input.result, input.result);
    for (size_t i = code.size(); i-- > 0;) {
        Instruction in = code[i];
        Role role = roleOf(in.op);
        if (role == Role::Point) {
            if (!pointLive[static_cast<size_t>(in.dst)]) continue;
            pointLive[static_cast<size_t>(in.dst)] = 0;
            pointLive[static_cast<size_t>(in.a)] = 1;
            kept.push_back(in);
            continue;
        }
        if (target[static_cast<size_t>(in.dst)] == -1) continue;  // dead
        int where = define(in.dst);
        switch (role) {
        case Role::Shape: pointLive[static_cast<size_t>(in.a)] = 1; break;
        case Role::Constant: break;
        case Role::Post:
            if (!need(in.a, where)) return false;
            in.a = where;
            pointLive[static_cast<size_t>(in.b)] = 1;
            break;
        case Role::Combine:
            if (outcomes[i] == Outcome::OnlyA) {
                if (!need(in.a, where)) return false;
                continue;
            }
            if (outcomes[i] == Outcome::OnlyB) {
                if (!need(in.b, where)) return false;
                continue;
            }
            {
                int a = in.a == in.dst ? where : in.a;
                if (!need(in.a, a) || !need(in.b, in.b)) return false;
                in.a = a;
            }
            break;
        case Role::Point: break;
        }
        in.dst = where;
        kept.push_back(in);
    }
    std::reverse(kept.begin(), kept.end());
    output.code = std::move(kept);
    output.result = input.result;
    return true;
}

}  // namespace

struct CellPruner::Workspace {
    f64::Scratch scratch;
    std::vector<PointBound> points;
    std::vector<Range> samples;
    std::vector<Outcome> outcomes;

    explicit Workspace(const program::Program& program) : scratch(program) {}
};

CellPruner::CellPruner(const program::Program& program)
    : program_(program), workspace_(std::make_unique<Workspace>(program)) {}

CellPruner::~CellPruner() = default;

CodeSpan CellPruner::prune(const CodeSpan& input, const glm::dvec3& centre, double radius) {
    const std::vector<Instruction>& code = input.code;
    const glm::dvec4* params = program_.params.data();
    Workspace& w = *workspace_;
    w.points.assign(static_cast<size_t>(program_.pointRegisters), PointBound{centre, radius});
    w.samples.assign(static_cast<size_t>(program_.sampleRegisters), unknownRange());
    w.outcomes.assign(code.size(), Outcome::Both);
    const double scale = glm::length(centre) + radius;
    bool saves = false;
    for (size_t i = 0; i < code.size(); ++i) {
        const Instruction& in = code[i];
        const glm::dvec4* q = in.param >= 0 ? params + in.param : nullptr;
        Role role = roleOf(in.op);
        if (role == Role::Point || role == Role::Shape) {
            // the value at the centre, with the interpreter both backends share
            f64::runCode(std::span<const Instruction>(&in, 1), 0, params, w.scratch, centre);
        }
        switch (role) {
        case Role::Point: {
            const PointBound& p = w.points[static_cast<size_t>(in.a)];
            w.points[static_cast<size_t>(in.dst)] = {w.scratch.points[static_cast<size_t>(in.dst)], pointRadius(in, p, q)};
            break;
        }
        case Role::Shape: {
            double r = w.points[static_cast<size_t>(in.a)].radius * shapeLipschitz(in.op);
            const auto& s = w.scratch.samples[static_cast<size_t>(in.dst)];
            if (!std::isfinite(r)) {
                w.samples[static_cast<size_t>(in.dst)] = unknownRange();
            } else if (in.op == Opcode::Ground) {
                w.samples[static_cast<size_t>(in.dst)] = groundRange(s.d, r, q[0].w > 0.0);
            } else {
                w.samples[static_cast<size_t>(in.dst)] = around(s.d, s.step, r);
            }
            break;
        }
        case Role::Combine: {
            Range result;
            w.outcomes[i] = decide(in, w.samples[static_cast<size_t>(in.a)], w.samples[static_cast<size_t>(in.b)], q,
                                   scale, result);
            saves = saves || w.outcomes[i] != Outcome::Both;
            w.samples[static_cast<size_t>(in.dst)] = result;
            break;
        }
        case Role::Post:
            w.samples[static_cast<size_t>(in.dst)] = postRange(in, w.samples[static_cast<size_t>(in.a)], q);
            break;
        case Role::Constant: w.samples[static_cast<size_t>(in.dst)] = around(1e10, 1e10, 0.0); break;
        }
    }
    CodeSpan output;
    if (!saves || !rewrite(program_, input, w.outcomes, output)) {
        return input;
    }
    return output;
}

CodeSpan pruneForCell(const program::Program& program, const CodeSpan& input, const glm::dvec3& centre,
                      double radius) {
    return CellPruner(program).prune(input, centre, radius);
}

}  // namespace sdfwb::prune
