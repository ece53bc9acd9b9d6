#include <gtest/gtest.h>

#include "scene/scene_json.h"

namespace sdfwb::scene {
namespace {

// Wraps a root node and extra top-level members into a complete scene document.
std::string document(const std::string& root, const std::string& extra = "") {
    return R"({"format": "sdf-workbench-scene", "version": 1, )" + extra + R"("root": )" + root + "}";
}

std::vector<std::string> problemsOf(const std::string& text) {
    try {
        parseScene(text);
    } catch (const SceneError& error) {
        return error.problems();
    }
    return {};
}

struct ErrorCase {
    const char* label;
    std::string text;
    std::string expected;  // the first problem, exactly
};

void PrintTo(const ErrorCase& c, std::ostream* out) { *out << c.label; }

class SceneValidation : public ::testing::TestWithParam<ErrorCase> {};

TEST_P(SceneValidation, ReportsPathAndReason) {
    auto problems = problemsOf(GetParam().text);
    ASSERT_FALSE(problems.empty());
    EXPECT_EQ(problems.front(), GetParam().expected);
}

const std::string kUnion = R"({"kind": "union", "children": [{"kind": "sphere"}, {"kind": "box"}, )";

INSTANTIATE_TEST_SUITE_P(
    Cases, SceneValidation,
    ::testing::Values(
        ErrorCase{"negative_radius", document(kUnion + R"({"kind": "sphere", "radius": -1}]})"),
                  "root.children[2].radius: must be > 0 (got -1)"},
        ErrorCase{"unknown_field", document(R"({"kind": "sphere", "radus": 2})"),
                  "root.radus: unknown field (sphere has: hidden, kind, material, name, radius, solo)"},
        ErrorCase{"unknown_kind", document(R"({"kind": "spere"})"),
                  "root.kind: unknown node kind \"spere\" (known: sphere, box, round_box, plane, torus, cone, "
                  "ellipsoid, cylinder, capsule, union, intersection, difference, smooth_union, "
                  "smooth_intersection, smooth_difference, translate, rotate, scale, twist, bend, round, "
                  "displace, elongate, mirror, repeat, repeat_infinite, sdf, implicit, polynomial)"},
        ErrorCase{"wrong_vector", document(R"({"kind": "box", "half_extents": [1, 2]})"),
                  "root.half_extents: must be an array of 3 numbers"},
        ErrorCase{"zero_half_extent", document(R"({"kind": "box", "half_extents": [1, 0, 1]})"),
                  "root.half_extents: component 1 must be > 0 (got 0)"},
        ErrorCase{"bad_variant", document(R"({"kind": "smooth_union", "variant": "cubic"})"),
                  "root.variant: must be one of polynomial, exponential, power, root (got \"cubic\")"},
        ErrorCase{"bad_exponent", document(R"({"kind": "smooth_union", "exponent": 4})"),
                  "root.exponent: must be 2 or 3 (got 4)"},
        ErrorCase{"unary_without_child", document(R"({"kind": "translate", "offset": [1, 0, 0]})"),
                  "root.children: translate needs exactly 1 child (got 0)"},
        ErrorCase{"infinite_number", document(R"({"kind": "sphere", "radius": 1e400})"),
                  "line 1, column 86: invalid JSON: number overflow \"1e400\" (numbers must be finite)"},
        ErrorCase{"missing_material", document(R"({"kind": "sphere", "material": "gold"})"),
                  "root.material: no material named \"gold\" in materials"},
        ErrorCase{"too_many_lights", document(R"({"kind": "sphere"})", R"("lights": [{}, {}, {}, {}, {}, {}, {}, {}, {}], )"),
                  "lights: at most 8 lights (got 9)"},
        ErrorCase{"aa_range", document(R"({"kind": "sphere"})", R"("render": {"aa": 9}, )"),
                  "render.aa: must be a whole number from 1 to 8 (got 9)"},
        ErrorCase{"shadow_mode", document(R"({"kind": "sphere"})", R"("render": {"shadows": "fuzzy"}, )"),
                  "render.shadows: must be one of none, hard, soft, improved (got \"fuzzy\")"},
        ErrorCase{"zero_light_direction", document(R"({"kind": "sphere"})", R"("lights": [{"direction": [0, 0, 0]}], )"),
                  "lights[0].direction: must not be the zero vector"},
        ErrorCase{"camera_elevation", document(R"({"kind": "sphere"})", R"("camera": {"elevation": 95}, )"),
                  "camera.elevation: must be from -90 to 90 degrees (got 95)"},
        ErrorCase{"unsupported_version", R"({"format": "sdf-workbench-scene", "version": 7, "root": {"kind": "sphere"}})",
                  "version: unsupported version 7 (this build reads versions 1 to 1)"},
        ErrorCase{"wrong_format", R"({"format": "something-else", "version": 1})",
                  "format: must be \"sdf-workbench-scene\""},
        ErrorCase{"duplicate_material", document(R"({"kind": "sphere"})", R"("materials": [{"name": "a"}, {"name": "a"}], )"),
                  "materials[1].name: duplicate material name \"a\""},
        ErrorCase{"formula_syntax", document(R"({"kind": "sdf", "formula": "length(p) - "})"),
                  "root.formula: column 13: expected an expression"},
        ErrorCase{"formula_unknown_name", document(R"({"kind": "implicit", "formula": "x^2 + q"})"),
                  "root.formula: column 7: unknown name 'q' (a formula over space uses p, x, y, z and its let names)"},
        ErrorCase{"not_a_polynomial", document(R"({"kind": "polynomial", "formula": "sqrt(x) - 1"})"),
                  "root.formula: column 1: 'sqrt' is not a polynomial or rational function"},
        // c*x*c keeps c*c apart; its x derivative folds it past the limit on
        // exact constants (each c has about 188,000 digits): refused at load,
        // as the compiler would refuse it, for each formula kind
        ErrorCase{"gradient_too_large_sdf",
                  document(R"({"kind": "sdf", "formula": "((3^65536)^6)*x*((3^65536)^6) + length(p) - 1"})"),
                  "root.formula: column 16: the number is too large to compute exactly (about 375224 digits; at "
                  "most 315652)"},
        ErrorCase{"gradient_too_large_implicit",
                  document(R"({"kind": "implicit", "formula": "((3^65536)^6)*x*((3^65536)^6) + y^2 + z^2 - 1"})"),
                  "root.formula: column 16: the number is too large to compute exactly (about 375224 digits; at "
                  "most 315652)"},
        ErrorCase{"gradient_too_large_polynomial",
                  document(R"({"kind": "polynomial", "formula": "((3^65536)^6)*x*((3^65536)^6) + y^2 + z^2 - 1"})"),
                  "root.formula: column 16: the number is too large to compute exactly (about 375224 digits; at "
                  "most 315652)"},
        ErrorCase{"bounds_order", document(R"({"kind": "implicit", "bounds_min": [1, 0, 0], "bounds_max": [0, 1, 1]})"),
                  "root.bounds_max: must be greater than bounds_min in every component"},
        ErrorCase{"malformed_json", "{\n  \"format\": \"sdf-workbench-scene\",\n  \"version\": 1,,\n}",
                  "line 3, column 16: invalid JSON: syntax error while parsing object key - unexpected ','; "
                  "expected string literal"}),
    [](const ::testing::TestParamInfo<ErrorCase>& info) { return info.param.label; });

TEST(SceneValidationAll, ReportsEveryProblemNotJustTheFirst) {
    auto problems = problemsOf(document(
        R"({"kind": "union", "children": [{"kind": "sphere", "radius": -1}, {"kind": "torus", "minor_radius": 0}]})",
        R"("render": {"aa": 0}, )"));
    ASSERT_EQ(problems.size(), 3u);
    EXPECT_EQ(problems[0], "render.aa: must be a whole number from 1 to 8 (got 0)");
    EXPECT_EQ(problems[1], "root.children[0].radius: must be > 0 (got -1)");
    EXPECT_EQ(problems[2], "root.children[1].minor_radius: must be > 0 (got 0)");
}

TEST(SceneValidationAll, FileErrorsNameTheFile) {
    try {
        loadSceneFile("/nonexistent/scene.json");
        FAIL() << "expected an error";
    } catch (const SceneError& error) {
        EXPECT_EQ(error.problems().front(), "cannot read /nonexistent/scene.json: No such file or directory");
    }
}

}  // namespace
}  // namespace sdfwb::scene
