#include "scene/node_kinds.h"

#include <array>
#include <cmath>
#include <sstream>

#include "algebra/ring.h"
#include "expr/derivative.h"
#include "expr/formula.h"
#include "expr/to_algebra.h"

namespace sdfwb::scene {
namespace {

using glm::dvec3;
using enum FieldType;
using enum Range;

constexpr std::string_view kMirrorAxes[] = {"x", "y", "z", "xy", "xz", "yz", "xyz"};

// Each field's `help` is its tooltip in the inspector (tests/scene checks every field has one).
FieldSpec real(std::string_view name, Range range, double value, std::string_view help, std::string_view unit = "") {
    return {name, Real, range, value, {}, unit, help};
}
FieldSpec vec3(std::string_view name, Range range, dvec3 value, std::string_view help, std::string_view unit = "") {
    return {name, Vec3, range, value, {}, unit, help};
}
FieldSpec choice(std::string_view name, std::span<const std::string_view> choices, std::string_view help) {
    return {name, Choice, Any, std::string(choices.front()), choices, "", help};
}
FieldSpec material() {
    return {
        "material", Material, Any, std::string(), {}, "", "The scene material it is drawn with; empty: the default"};
}

const std::array kSphere = {real("radius", Positive, 1.0, "Distance from the centre to the surface"), material()};
const std::array kBox = {vec3("half_extents", Positive, dvec3(1.0), "Half the size along x, y and z"), material()};
const std::array kRoundBox = {vec3("half_extents", Positive, dvec3(1.0), "Half the size along x, y and z"),
                              real("radius", NonNegative, 0.1, "Radius of the rounded edges and corners"), material()};
const std::array kPlane = {vec3("normal", NonZeroVector, dvec3(0, 1, 0), "Direction the plane faces (normalized)"),
                           real("offset", Any, 0.0, "Distance of the plane from the origin along the normal"),
                           material()};
const std::array kTorus = {real("major_radius", Positive, 1.0, "Radius of the ring's centre line, in the xz plane"),
                           real("minor_radius", Positive, 0.25, "Radius of the tube"), material()};
const std::array kCone = {real("angle", OpenAngle90, 30.0, "Angle between the side and the base (the half-angle at the apex is 90 minus it)", "degrees"),
                          real("height", Positive, 1.0, "Distance from the apex down to the base"), material()};
const std::array kEllipsoid = {vec3("radii", Positive, dvec3(1.0, 0.6, 0.8), "Semi-axes along x, y and z"), material()};
const std::array kCylinder = {real("radius", Positive, 0.5, "Radius about the y axis"),
                              real("half_height", Positive, 1.0, "Half the height along y"), material()};
const std::array kCapsule = {vec3("a", Any, dvec3(0, -0.5, 0), "One end of the axis segment"),
                             vec3("b", Any, dvec3(0, 0.5, 0), "The other end of the axis segment"),
                             real("radius", Positive, 0.25, "Distance of the surface from the segment"), material()};
const std::array<FieldSpec, 0> kNoFields = {};
const std::array kSmooth = {real("k", NonNegative, 0.25, "Width of the blend region; 0 is the sharp operation"),
                            choice("variant", kSmoothVariantNames, "Which smooth minimum blends the children"),
                            real("exponent", Integer2or3, 2.0, "Degree of the polynomial smooth minimum (2 or 3)")};
const std::array kTranslate = {vec3("offset", Any, dvec3(0.0), "Moves the child by this vector")};
const std::array kRotate = {vec3("angles", Any, dvec3(0.0), "Turns the child about x, then y, then z", "degrees")};
const std::array kScale = {real("factor", Positive, 1.0, "Uniform scale of the child (the distance scales with it)")};
const std::array kTwist = {real("k", Any, 1.0, "Twist about the y axis per unit of height", "radians per unit")};
const std::array kBend = {real("k", Any, 0.5, "Bend in the xy plane per unit along x", "radians per unit")};
const std::array kRound = {real("radius", NonNegative, 0.1, "Grows the child by this much, rounding its edges")};
const std::array kDisplace = {real("amplitude", Any, 0.05, "Height of the sine ripples added to the surface"),
                              real("frequency", Any, 10.0, "Angular frequency of the ripples", "radians per unit")};
const std::array kElongate = {
    vec3("h", NonNegative, dvec3(0.5, 0.0, 0.0), "Stretches the child's middle by twice this per axis")};
const std::array kMirror = {choice("axes", kMirrorAxes, "Axes across whose planes the child is mirrored")};
const std::array kRepeat = {
    vec3("spacing", NonNegative, dvec3(2.0, 0.0, 2.0), "Distance between copies per axis (0: no repetition)"),
    vec3("counts", NonNegativeInteger, dvec3(1.0, 0.0, 1.0), "Copies on each side of the original per axis")};
const std::array kRepeatInfinite = {
    vec3("period", NonNegative, dvec3(2.0, 0.0, 2.0), "Distance between copies per axis, without end (0: none)")};
FieldSpec formula(Range kind, std::string_view value, std::string_view help) {
    return {"formula", Formula, kind, std::string(value), {}, "", help};
}
const std::array kSdf = {formula(SdfFormula, "length(p) - 1", "A signed distance in p (or x, y, z): negative inside"),
                         material()};
// sheet_thickness 0: the solid F <= 0; more: a sheet that thick around F = 0
// (open surfaces such as the Moebius strip have no inside worth showing)
constexpr std::string_view kBoundsMin = "Lower corner of the box the surface is searched in";
constexpr std::string_view kBoundsMax = "Upper corner of the box the surface is searched in";
constexpr std::string_view kMaxStep = "Longest march step inside the box (smaller: thin features are not skipped)";
constexpr std::string_view kSheet = "0: the solid F <= 0; more: a sheet this thick around F = 0";
const std::array kImplicit = {formula(ImplicitFormula, "x^2 + y^2 + z^2 - 1", "An equation F(x, y, z) = 0 (write F)"),
                              vec3("bounds_min", Any, dvec3(-1.5), kBoundsMin),
                              vec3("bounds_max", Any, dvec3(1.5), kBoundsMax),
                              real("max_step", Positive, 0.25, kMaxStep),
                              real("sheet_thickness", NonNegative, 0.0, kSheet),
                              material()};
const std::array kPolynomial = {
    formula(PolynomialFormula, "x^2 + y^2 + z^2 - 1", "A polynomial F(x, y, z); the surface is F = 0"),
    vec3("bounds_min", Any, dvec3(-1.5), kBoundsMin),
    vec3("bounds_max", Any, dvec3(1.5), kBoundsMax),
    real("max_step", Positive, 0.25, kMaxStep),
    real("sheet_thickness", NonNegative, 0.0, kSheet),
    material()};

using enum NodeKind;
using enum NodeCategory;
using enum DistanceQuality;

const std::array<KindSpec, kNodeKindCount> kKinds = {{
    {Sphere, "sphere", Primitive, Exact, 0, 0, kSphere},
    {Box, "box", Primitive, Exact, 0, 0, kBox},
    {RoundBox, "round_box", Primitive, Exact, 0, 0, kRoundBox},
    {Plane, "plane", Primitive, Exact, 0, 0, kPlane},
    {Torus, "torus", Primitive, Exact, 0, 0, kTorus},
    {Cone, "cone", Primitive, Bound, 0, 0, kCone},
    {Ellipsoid, "ellipsoid", Primitive, Bound, 0, 0, kEllipsoid},
    {Cylinder, "cylinder", Primitive, Exact, 0, 0, kCylinder},
    {Capsule, "capsule", Primitive, Exact, 0, 0, kCapsule},
    {Union, "union", Boolean, Bound, 0, -1, kNoFields},
    {Intersection, "intersection", Boolean, Bound, 0, -1, kNoFields},
    {Difference, "difference", Boolean, Bound, 0, -1, kNoFields},
    {SmoothUnion, "smooth_union", Boolean, Bound, 0, -1, kSmooth},
    {SmoothIntersection, "smooth_intersection", Boolean, Bound, 0, -1, kSmooth},
    {SmoothDifference, "smooth_difference", Boolean, Bound, 0, -1, kSmooth},
    {Translate, "translate", Affine, Exact, 1, 1, kTranslate},
    {Rotate, "rotate", Affine, Exact, 1, 1, kRotate},
    {Scale, "scale", Affine, Exact, 1, 1, kScale},
    {Twist, "twist", Deforming, Bound, 1, 1, kTwist},
    {Bend, "bend", Deforming, Bound, 1, 1, kBend},
    {Round, "round", Deforming, Exact, 1, 1, kRound},
    {Displace, "displace", Deforming, Bound, 1, 1, kDisplace},
    {Elongate, "elongate", Deforming, Exact, 1, 1, kElongate},
    {Mirror, "mirror", Repetition, Bound, 1, 1, kMirror},
    {Repeat, "repeat", Repetition, Bound, 1, 1, kRepeat},
    {RepeatInfinite, "repeat_infinite", Repetition, Bound, 1, 1, kRepeatInfinite},
    {Sdf, "sdf", Primitive, Exact, 0, 0, kSdf},
    {Implicit, "implicit", Primitive, Bound, 0, 0, kImplicit},
    {Polynomial, "polynomial", Primitive, Bound, 0, 0, kPolynomial},
}};

// Checks what the scene compiler builds from the formula, so that a scene
// that loads also compiles: the formula and its gradient (implicit surfaces
// always use it, a distance formula for a triplanar texture), whose
// derivatives fold constants that can pass their limit where the formula's
// own did not ("c*x*c" keeps c*c apart, its x derivative folds it).
std::string checkFormula(Range kind, const std::string& text) {
    try {
        switch (kind) {
        case SdfFormula:
        case ImplicitFormula:
        case PolynomialFormula: {
            expr::SpaceFormula f = kind == SdfFormula ? expr::compileSdf(text) : expr::compileImplicit(text);
            if (kind == PolynomialFormula) {
                expr::toPolynomial(f.graph, f.value, sdfwb::algebra::Ring::make({"x", "y", "z"}));
            }
            expr::gradient(f.graph, f.value);
            break;
        }
        default: break;
        }
    } catch (const std::exception& error) {
        return error.what();
    }
    return "";
}

}  // namespace

std::string formatNumber(double v) {
    std::ostringstream out;
    out << v;
    return out.str();
}

std::string checkScalar(Range range, double v) {
    if (!std::isfinite(v)) {
        return "must be a finite number";
    }
    switch (range) {
    case Positive: return v > 0 ? "" : "must be > 0 (got " + formatNumber(v) + ")";
    case NonNegative: return v >= 0 ? "" : "must be >= 0 (got " + formatNumber(v) + ")";
    case Integer2or3: return (v == 2 || v == 3) ? "" : "must be 2 or 3 (got " + formatNumber(v) + ")";
    case NonNegativeInteger:
        return (v >= 0 && v == std::floor(v) && v <= 1e6) ? ""
                                                          : "must be a whole number >= 0 (got " + formatNumber(v) + ")";
    case OpenAngle90:
        return (v > 0 && v < 90) ? "" : "must be strictly between 0 and 90 degrees (got " + formatNumber(v) + ")";
    default: return "";
    }
}

const KindSpec& kindSpec(NodeKind kind) { return kKinds[static_cast<size_t>(kind)]; }

const KindSpec* findKind(std::string_view name) {
    for (const KindSpec& spec : kKinds) {
        if (spec.name == name) {
            return &spec;
        }
    }
    return nullptr;
}

std::span<const KindSpec> allKinds() { return kKinds; }

int fieldIndex(const KindSpec& spec, std::string_view field) {
    for (size_t i = 0; i < spec.fields.size(); ++i) {
        if (spec.fields[i].name == field) {
            return static_cast<int>(i);
        }
    }
    return -1;
}

std::string checkField(const FieldSpec& field, const FieldValue& value) {
    switch (field.type) {
    case Real:
        if (!std::holds_alternative<double>(value)) {
            return "must be a number";
        }
        return checkScalar(field.range, std::get<double>(value));
    case Vec3: {
        if (!std::holds_alternative<dvec3>(value)) {
            return "must be an array of 3 numbers";
        }
        const dvec3& v = std::get<dvec3>(value);
        for (int i = 0; i < 3; ++i) {
            std::string problem = checkScalar(field.range, v[i]);
            if (!problem.empty()) {
                return "component " + std::to_string(i) + " " + problem;
            }
        }
        if (field.range == NonZeroVector && v == dvec3(0.0)) {
            return "must not be the zero vector";
        }
        return "";
    }
    case Choice: {
        if (!std::holds_alternative<std::string>(value)) {
            return "must be a string";
        }
        const std::string& s = std::get<std::string>(value);
        std::string list;
        for (std::string_view c : field.choices) {
            if (c == s) {
                return "";
            }
            list += (list.empty() ? "" : ", ") + std::string(c);
        }
        return "must be one of " + list + " (got \"" + s + "\")";
    }
    case Material: return std::holds_alternative<std::string>(value) ? "" : "must be a material name";
    case Formula:
        if (!std::holds_alternative<std::string>(value)) {
            return "must be a string";
        }
        return checkFormula(field.range, std::get<std::string>(value));
    }
    return "";
}

std::vector<std::pair<std::string, std::string>> checkNodeFields(const KindSpec& spec,
                                                                 const std::vector<FieldValue>& values) {
    std::vector<std::pair<std::string, std::string>> problems;
    int lo = fieldIndex(spec, "bounds_min"), hi = fieldIndex(spec, "bounds_max");
    if (lo >= 0 && hi >= 0) {
        const dvec3* a = std::get_if<dvec3>(&values[static_cast<size_t>(lo)]);
        const dvec3* b = std::get_if<dvec3>(&values[static_cast<size_t>(hi)]);
        if (a && b && !(a->x < b->x && a->y < b->y && a->z < b->z)) {
            problems.emplace_back("bounds_max", "must be greater than bounds_min in every component");
        }
    }
    return problems;
}

}  // namespace sdfwb::scene
