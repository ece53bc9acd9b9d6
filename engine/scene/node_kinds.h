#pragma once
// The node kinds of the scene tree and their fields: one table drives JSON
// loading and saving, validation, the compiler's field lookups and the editor.

#include <iterator>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include <glm/vec3.hpp>

namespace sdfwb::scene {

enum class NodeKind {
    // primitives
    Sphere, Box, RoundBox, Plane, Torus, Cone, Ellipsoid, Cylinder, Capsule,
    // booleans, folded in child order
    Union, Intersection, Difference, SmoothUnion, SmoothIntersection, SmoothDifference,
    // affine
    Translate, Rotate, Scale,
    // deforming
    Twist, Bend, Round, Displace, Elongate,
    // repetition
    Mirror, Repeat, RepeatInfinite,
    // primitives given by a formula (docs/expression-language.md, docs/implicit-surfaces.md)
    Sdf, Implicit, Polynomial,
};
inline constexpr int kNodeKindCount = static_cast<int>(NodeKind::Polynomial) + 1;

// True when table[i].kind == NodeKind(i) for every kind: the check that keeps the
// tables other layers key by kind (compile rules, bounds rules) complete and in order.
template <typename Table>
constexpr bool inKindOrder(const Table& table) {
    if (table.size() != static_cast<size_t>(kNodeKindCount)) return false;
    for (size_t i = 0; i < table.size(); ++i) {
        if (static_cast<size_t>(table[i].kind) != i) return false;
    }
    return true;
}

// The variants of the smooth booleans' "variant" field, with their JSON names in
// enum order; the shared library's SMOOTH_* codes are checked against them.
enum class SmoothVariant { Polynomial, Exponential, Power, Root };
inline constexpr std::string_view kSmoothVariantNames[] = {"polynomial", "exponential", "power", "root"};
static_assert(std::size(kSmoothVariantNames) == static_cast<size_t>(SmoothVariant::Root) + 1);

enum class NodeCategory { Primitive, Boolean, Affine, Deforming, Repetition };

// Whether a primitive's or operator's field is an exact signed distance or a bound
// (|f| <= true distance, same sign). Tests check the label.
enum class DistanceQuality { Exact, Bound };

enum class FieldType {
    Real,      // double
    Vec3,      // glm::dvec3
    Choice,    // std::string, one of FieldSpec::choices
    Material,  // std::string, the name of a scene material ("" = the default material)
    Formula,   // std::string in the formula language; Range says which kind
};

// Constraint on a Real field, or on every component of a Vec3 field.
enum class Range {
    Any, Positive, NonNegative, Integer2or3, NonNegativeInteger, OpenAngle90, NonZeroVector,
    // Formula fields: a signed distance, an implicit equation F = 0, a polynomial in x, y, z
    SdfFormula, ImplicitFormula, PolynomialFormula,
};

using FieldValue = std::variant<double, glm::dvec3, std::string>;

struct FieldSpec {
    std::string_view name;
    FieldType type;
    Range range;
    FieldValue defaultValue;
    std::span<const std::string_view> choices;  // Choice fields only
    std::string_view unit;                       // for documentation and the editor
    std::string_view help;                       // one sentence: the inspector's tooltip
};

struct KindSpec {
    NodeKind kind;
    std::string_view name;  // JSON "kind"
    NodeCategory category;
    DistanceQuality quality;
    int minChildren;
    int maxChildren;  // -1: any number
    std::span<const FieldSpec> fields;
};

const KindSpec& kindSpec(NodeKind kind);
// nullptr when `name` is not a node kind.
const KindSpec* findKind(std::string_view name);
std::span<const KindSpec> allKinds();

// Index of `field` in spec.fields, or -1.
int fieldIndex(const KindSpec& spec, std::string_view field);

// Empty when `value` satisfies the field's type and range; otherwise the reason,
// phrased to follow "<path>: ", e.g. "must be > 0 (got -1)" or, for a formula,
// "column 7: expected ')' after function arguments".
std::string checkField(const FieldSpec& field, const FieldValue& value);
// The rule of one number under `range` (a finite number first), worded as checkField words it.
std::string checkScalar(Range range, double v);
// A number as the problem messages quote it ("0.5", "1e+300").
std::string formatNumber(double v);

// Problems that involve several fields of one node (e.g. bounds_min < bounds_max),
// as (field name, reason) pairs.
std::vector<std::pair<std::string, std::string>> checkNodeFields(const KindSpec& spec,
                                                                 const std::vector<FieldValue>& values);

}  // namespace sdfwb::scene
