#pragma once
// Which edits of a scene keep its prune grids (prune/prune_grid.h): a caller
// that must not wait for a grid (the window's preview) uses it to expect one
// still to be built after an edit, and a whole-program render meanwhile.

#include "scene/scene.h"

namespace sdfwb::prune {

// True only when `after` differs from `before` in the lights' directions
// and colours, which no grid reads: relighting. Anything else is taken to
// need new grids, even where it may not (a material's colour keeps them, but
// a material turned into glass changes the program's structure, and with it
// the grid's key): the answer errs towards a rebuild. A camera move builds
// new grids: programs are compiled relative to the eye (their parameters and
// bounds move with it).
bool keepsPruneGrids(const scene::Scene& before, const scene::Scene& after);

}  // namespace sdfwb::prune
