// One guard rule for the GLSL built-ins that are undefined on part of their
// domain: the shared library's wrappers (sdf/glsl/math.glsl) and the formula
// language (expr/builtins.cpp) give the values of the table in
// docs/shared-glsl-subset.md, in float and double. The library's sources call
// no raw built-in that has a guarded or bit-exact twin.

#include <cmath>
#include <fstream>
#include <limits>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "formula_eval.h"
#include "sdf/glsl_sources.h"
#include "sdf/shared.h"
#include "support/source_tree.h"

namespace sdfwb {
namespace {

using expr::testing::sdfAt;

// The GLSL built-ins the library must not call: each has a twin that is
// guarded or rounds alike in GLSL and C++ (docs/shared-glsl-subset.md).
const std::vector<std::string> kBuiltinsWithTwins = {"dot",  "length", "distance", "normalize", "mix", "smoothstep",
                                                     "step", "mod",    "round",    "pow",       "sin", "cos",
                                                     "tan",  "exp",    "log",      "fract",     "sign"};

// The library's text without comments.
std::string librarySourceWithoutComments() {
    std::string text =
        std::string(sdf::glslPrelude()) + std::string(sdf::glslLibrary()) + std::string(sdf::glslSampleDriver());
    return std::regex_replace(text, std::regex("//[^\n]*"), "");
}

TEST(BuiltinGuards, TheLibraryCallsNoBuiltinThatHasATwin) {
    const std::string text = librarySourceWithoutComments();
    for (const std::string& name : kBuiltinsWithTwins) {
        // a call, not a member (.x), a longer name (dot3) or a declaration of the twin
        std::regex call("(^|[^A-Za-z0-9_.])" + name + "\\s*\\(");
        std::smatch match;
        EXPECT_FALSE(std::regex_search(text, match, call))
            << "the shared library calls " << name << "(: use its twin (docs/shared-glsl-subset.md)";
    }
}

TEST(BuiltinGuards, TheDocumentedTableNamesEveryGuardedBuiltin) {
    std::ifstream in(sdfwb::test::sourceDir() + "/docs/shared-glsl-subset.md");
    ASSERT_TRUE(in);
    std::stringstream doc;
    doc << in.rdbuf();
    for (const char* row :
         {"| `sqrt(x)`, x < 0 |", "| `mod(x, 0)` |", "| `smoothstep(e, e, x)` |", "| `normalize(0)` (*differs*) |",
          "| `pow(x, y)`, x <= 0 (*differs*) |", "| `log(x)`, x <= 0 |",
          "| `min(a, b)`, `max(a, b)`, `clamp(x, lo, hi)`, an operand NaN |"}) {
        EXPECT_NE(doc.str().find(row), std::string::npos) << "docs/shared-glsl-subset.md lacks the row " << row;
    }
}

// The library's side of each row.
template <class Real, class Vec3, class F>
void expectLibraryRows(F normalize3, Real (*safeSqrt)(Real), Real (*modr)(Real, Real),
                       Real (*smoothstepr)(Real, Real, Real), Real (*safePow)(Real, Real), Real (*minr)(Real, Real),
                       Real (*maxr)(Real, Real), Real (*clampr)(Real, Real, Real)) {
    const Real nan = std::numeric_limits<Real>::quiet_NaN();
    EXPECT_EQ(minr(nan, Real(1)), Real(1));
    EXPECT_EQ(minr(Real(1), nan), Real(1));
    EXPECT_EQ(maxr(nan, Real(-1)), Real(-1));
    EXPECT_EQ(maxr(Real(-1), nan), Real(-1));
    EXPECT_TRUE(std::isnan(minr(nan, nan)));
    EXPECT_EQ(clampr(nan, Real(-1), Real(1)), Real(-1));
    EXPECT_EQ(safeSqrt(nan), Real(0)) << "sqrt(max(NaN, 0))";
    EXPECT_EQ(safeSqrt(Real(-4)), Real(0));
    EXPECT_EQ(modr(Real(2.5), Real(0)), Real(2.5));
    EXPECT_EQ(modr(Real(-2.5), Real(0)), Real(-2.5));
    EXPECT_EQ(smoothstepr(Real(1), Real(1), Real(0.5)), Real(0));
    EXPECT_EQ(smoothstepr(Real(1), Real(1), Real(1)), Real(1));
    EXPECT_EQ(smoothstepr(Real(1), Real(1), Real(3)), Real(1));
    EXPECT_EQ(normalize3(Vec3(Real(0))), Vec3(Real(0), Real(0), Real(1)));
    EXPECT_EQ(safePow(Real(0), Real(2)), Real(0));
    EXPECT_EQ(safePow(Real(-2), Real(0.5)), Real(0));
    EXPECT_EQ(safePow(Real(-2), Real(-1)), Real(0));
}

TEST(BuiltinGuards, LibraryRowsInFloat) {
    namespace s = sdf::f32;
    expectLibraryRows<float, s::vec3>(s::normalize3, s::safeSqrt, s::modr, s::smoothstepr, s::safePow, s::min, s::max,
                                      s::clamp);
}

TEST(BuiltinGuards, LibraryRowsInDouble) {
    namespace s = sdf::f64;
    expectLibraryRows<double, s::vec3>(s::normalize3, s::safeSqrt, s::modr, s::smoothstepr, s::safePow, s::min, s::max,
                                       s::clamp);
}

// The formulas' side: each formula is evaluated at p = (x, 0, 0).
template <class Real>
Real formulaAt(const char* source, Real x) {
    return sdfAt<Real>(source, glm::vec<3, Real>(x, Real(0), Real(0)));
}

template <class Real>
void expectFormulaRows() {
    const Real tiny = std::ldexp(Real(1), -126);
    EXPECT_EQ(formulaAt<Real>("sqrt(x)", Real(-4)), Real(0));
    EXPECT_EQ(formulaAt<Real>("mod(x, y)", Real(2.5)), Real(2.5));
    EXPECT_EQ(formulaAt<Real>("mod(x, y)", Real(-2.5)), Real(-2.5));
    EXPECT_EQ(formulaAt<Real>("smoothstep(1.0, 1.0, x)", Real(0.5)), Real(0));
    EXPECT_EQ(formulaAt<Real>("smoothstep(1.0, 1.0, x)", Real(1)), Real(1));
    EXPECT_EQ(formulaAt<Real>("smoothstep(1.0, 1.0, x)", Real(3)), Real(1));
    EXPECT_EQ(formulaAt<Real>("abs(normalize(p).x) + abs(normalize(p).y) + abs(normalize(p).z)", Real(0)), Real(0));
    EXPECT_NEAR(formulaAt<Real>("pow(x, 0.5)", Real(-2)), std::sqrt(tiny), std::sqrt(tiny) * Real(1e-5));
    EXPECT_NEAR(formulaAt<Real>("pow(x, 0.5)", Real(0)), std::sqrt(tiny), std::sqrt(tiny) * Real(1e-5));
    EXPECT_NEAR(formulaAt<Real>("log(x)", Real(0)), std::log(tiny), Real(1e-4));
    EXPECT_NEAR(formulaAt<Real>("log(x)", Real(-1)), std::log(tiny), Real(1e-4));
    EXPECT_EQ(formulaAt<Real>("mix(3.0, x, 1.0)", Real(0.1)), Real(0.1)) << "a formula's mix is exact at t = 1";
    const Real nan = std::numeric_limits<Real>::quiet_NaN();
    EXPECT_EQ(formulaAt<Real>("min(x, 2.0)", nan), Real(2));
    EXPECT_EQ(formulaAt<Real>("max(2.0, x)", nan), Real(2));
    EXPECT_EQ(formulaAt<Real>("clamp(x, -1.0, 1.0)", nan), Real(-1));
}

TEST(BuiltinGuards, FormulaRowsInFloat) { expectFormulaRows<float>(); }
TEST(BuiltinGuards, FormulaRowsInDouble) { expectFormulaRows<double>(); }

// Where both are defined they are the same expression: a reversed smoothstep
// and an ordinary one agree bit for bit.
TEST(BuiltinGuards, SmoothstepAgreesWhereDefined) {
    for (float edge0 : {-1.0f, 2.0f}) {
        for (float x : {-3.0f, -0.25f, 0.0f, 0.4f, 1.0f, 2.5f}) {
            std::string source = "smoothstep(" + std::to_string(edge0) + ", 0.5, x)";
            EXPECT_EQ(formulaAt<float>(source.c_str(), x), sdf::f32::smoothstepr(edge0, 0.5f, x))
                << source << " at " << x;
        }
    }
}

}  // namespace
}  // namespace sdfwb
