#pragma once
// Per-region pruned programs: a coarse grid of cubic cells over the scene's
// bounds, each cell either a leaf holding the instructions that equal the
// whole program inside it (prune/cell_pruning.h) or split into 2x2x2 finer
// cells, down to a fixed depth. Built once per program on the host; both
// backends read the same leaves, so pruning never makes them differ.
//
// Outside the grid (farther from the scene's bounds than the margin) the field
// is a lower bound instead: the distance to the bounds' box, unioned with the
// ground plane when there is one. docs/large-scenes.md says why.

#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "program/program.h"

namespace sdfwb::prune {

struct PruneLeaf {
    int offset;  // first instruction in PruneGrid::code
    int count;
    int result;  // sample register holding the field
};

inline constexpr int kSplit = 2;  // children per axis of a split cell
inline constexpr int kMaxDepth = 5;  // splits below a root cell

struct PruneGrid {
    glm::dvec3 origin{0.0};     // march coordinates of the grid's minimum corner
    double cellSize = 0.0;      // side of a root cell
    glm::ivec3 dims{0};         // root cells per axis
    // nodes[i] >= 0: index of a leaf; < 0: -(first + 1), where nodes[first ...
    // first + 7] are the 2x2x2 children, x fastest. Root cells come first.
    std::vector<int> nodes;
    std::vector<PruneLeaf> leaves;
    std::vector<program::Instruction> code;
    int outsideLeaf = 0;
    // Parameter slots the outside bound reads, numbered after Program::params.
    std::vector<glm::dvec4> extraParams;
    int longestLeaf = 0;  // instructions
};

// The grid for `program`, or null when it has none: pruning is off
// (Program::prune), the scene's root is unbounded, or nothing can be saved.
// Grids are cached by the program's instructions and parameters.
std::shared_ptr<const PruneGrid> pruneGridFor(const program::Program& program);

// How many grids pruneGridFor has built in this process (its cache misses):
// the picker's tests check that a pick builds none.
long pruneGridsBuilt();

// Smaller programs are evaluated whole: a grid would cost more to build than
// it saves, and the GL backend (no pruning yet) renders them as they are.
inline constexpr int kMinPrunedInstructions = 128;

// Builds it without the cache; tests lower `minInstructions` to prune small scenes.
std::shared_ptr<const PruneGrid> buildPruneGrid(const program::Program& program,
                                                int minInstructions = kMinPrunedInstructions);

// The leaf whose instructions evaluate the field at march point p, computed in
// the precision of p (the same float operations in every backend).
template <typename Vec3>
int leafIndexAt(const PruneGrid& grid, Vec3 p) {
    using Real = typename Vec3::value_type;
    Vec3 q = (p - Vec3(grid.origin)) * Real(1.0 / grid.cellSize);
    if (!(q.x >= Real(0) && q.y >= Real(0) && q.z >= Real(0) && q.x < Real(grid.dims.x) && q.y < Real(grid.dims.y) &&
          q.z < Real(grid.dims.z))) {
        return grid.outsideLeaf;
    }
    Vec3 cell = glm::floor(q);
    int node = grid.nodes[static_cast<size_t>(int(cell.x) + grid.dims.x * (int(cell.y) + grid.dims.y * int(cell.z)))];
    while (node < 0) {
        // q - floor(q) is exact in floating point, so the split is too
        q = (q - cell) * Real(kSplit);
        cell = glm::floor(q);
        node = grid.nodes[static_cast<size_t>(-node - 1 + int(cell.x) + kSplit * (int(cell.y) + kSplit * int(cell.z)))];
    }
    return node;
}

}  // namespace sdfwb::prune
