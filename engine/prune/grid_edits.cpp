#include "prune/grid_edits.h"

namespace sdfwb::prune {

bool keepsPruneGrids(const scene::Scene& before, const scene::Scene& after) {
    if (before.lights.size() != after.lights.size()) return false;
    // `after` with what no grid reads taken back from `before`
    scene::Scene rest = after;
    for (size_t i = 0; i < rest.lights.size(); ++i) {
        rest.lights[i].direction = before.lights[i].direction;
        rest.lights[i].color = before.lights[i].color;
    }
    return rest == before;
}

}  // namespace sdfwb::prune
