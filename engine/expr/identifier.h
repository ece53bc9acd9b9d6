#pragma once
// The one identifier rule of the language. Every place that reads a user's
// name uses it: formulas, `let` bindings, parametrization parameters, and the
// CLI's `--vars`.

#include <string>
#include <string_view>

namespace sdfwb::expr {

// An identifier is an ASCII letter followed by ASCII letters, digits or
// underscores, and is not a reserved word (`let`, `vec2`, `vec3` or the name of
// a built-in function such as `sin`). Meaning is contextual, not lexical: in a
// formula over space `p`, `x`, `y`, `z` are the point and its coordinates; in a
// parametrization every identifier other than x, y, z is a parameter.
// Internal variables (half-angle parameters, ...) are named by
// algebra::internalVariableName, with a leading '$' no identifier has.
bool isIdentifier(std::string_view name);

// Why `name` is not an identifier, as a phrase for an error message
// ("'sin' is the name of a built-in function"); empty when it is one.
std::string identifierProblem(std::string_view name);

// x, y or z: the coordinates of space.
bool isCoordinate(std::string_view name);

}  // namespace sdfwb::expr
