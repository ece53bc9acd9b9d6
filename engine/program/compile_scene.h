#pragma once
// Compiling a scene into a Program.

#include "program/program.h"
#include "scene/scene.h"

namespace sdfwb::program {

struct CompileOptions {
    int width = 0;   // 0: the scene's render.width
    int height = 0;  // 0: the scene's render.height
    int aa = 0;      // 0: the scene's render.aa
    bool prune = true;  // false: no spatial pruning (a reference for tests and --no-prune)
};

// The scene must be valid (as loaded by sceneFromJson). Coordinates are shifted
// so that the eye is the origin; translations are folded into that shift in
// double precision, so a scene far from the world origin keeps float precision.
Program compileScene(const scene::Scene& scene, const CompileOptions& options = {});

// A user formula compiled to a tape of its value, or with `withGradient` of
// its value and gradient; x, y, z are variables 0, 1, 2.
// Throws expr::Error for a formula that does not compile.
FormulaCode compileFormula(const std::string& source, FormulaLanguage language, bool withGradient);

}  // namespace sdfwb::program
