// Fuzz target: the formula parser and compiler. A formula either compiles or
// fails with expr::Error; one that compiles also gets its gradient, its tape
// (evaluated at a point) and its GLSL, as a scene's implicit node would.

#include <cstdint>
#include <string_view>
#include <vector>

#include "expr/derivative.h"
#include "expr/formula.h"
#include "expr/glsl.h"
#include "expr/tape.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace sdfwb::expr;
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        SpaceFormula formula = compileImplicit(text);
        std::array<NodeId, 3> g = gradient(formula.graph, formula.value);
        const std::vector<NodeId> outputs = {formula.value, g[0], g[1], g[2]};
        const Tape tape(formula.graph, outputs);
        Evaluator<double> evaluate(tape);
        const double p[] = {0.25, -0.5, 0.75};
        evaluate(p);
        emitGlslBody(tape, {"x", "y", "z"});
    } catch (const Error&) {
    }
    return 0;
}
