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
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "program/program.h"
#include "sdf/shared.h"

namespace sdfwb::prune {

namespace lookup32 {
using namespace sdfwb::sdf::f32;
#include "prune/leaf_lookup.inl"
}  // namespace lookup32

namespace lookup64 {
using namespace sdfwb::sdf::f64;
#include "prune/leaf_lookup.inl"
}  // namespace lookup64

struct PruneLeaf {
    int offset;  // first instruction in PruneGrid::code
    int count;
    int result;  // sample register holding the field
};

inline constexpr int kSplit = sdf::f64::PRUNE_SPLIT;  // children per axis of a split cell
inline constexpr int kMaxDepth = sdf::f64::PRUNE_MAX_DEPTH;  // splits below a root cell

struct PruneGrid {
    glm::dvec3 origin{0.0};     // march coordinates of the grid's minimum corner
    double cellSize = 0.0;      // side of a root cell
    glm::ivec3 dims{0};         // root cells per axis
    // nodes[i] >= 0: index of a leaf; < 0: -(first + 1), where nodes[first ...
    // first + 7] are the 2x2x2 children, x fastest. Root cells come first.
    // Cells whose instructions are the same share one leaf.
    std::vector<int> nodes;
    std::vector<PruneLeaf> leaves;
    std::vector<program::Instruction> code;
    int outsideLeaf = 0;
    // Parameter slots numbered after Program::params: the outside bound's
    // (outsideBoundParams), then lookupFrame() and lookupDims().
    std::vector<glm::dvec4> extraParams;
    int longestLeaf = 0;  // instructions

    // pruneLeafAt's arguments (sdf/glsl/prune_lookup.glsl): (origin, 1 / cellSize)
    // and (dims, outsideLeaf), converted to the lookup's precision.
    glm::dvec4 lookupFrame() const { return glm::dvec4(origin, 1.0 / cellSize); }
    glm::dvec4 lookupDims() const { return glm::dvec4(glm::dvec3(dims), outsideLeaf); }
};

// The grid for `program`, or null when it has none: pruning is off
// (Program::prune), the scene's root is unbounded, or nothing can be saved.
// Grids are cached by what they depend on: the instructions and the
// parameters these read (a material or light colour edit keeps the grid). A
// caller asking for a grid another thread is building waits for that build.
std::shared_ptr<const PruneGrid> pruneGridFor(const program::Program& program);

// The cached grid (null: the program has none); nullopt while it is not
// built yet, and then a build starts on a background thread, for a caller
// that must not wait (the window's GL viewport draws without it meanwhile).
std::optional<std::shared_ptr<const PruneGrid>> pruneGridIfBuilt(const program::Program& program);

// How many grids pruneGridFor has built in this process (its cache misses):
// the picker's tests check that a pick builds none.
long pruneGridsBuilt();

// Smaller programs are evaluated whole: a grid would cost more to build than
// it saves (the GL backend's fold loop then keeps every block, gl/fold_run.h).
inline constexpr int kMinPrunedInstructions = 128;

// The field outside the grid: a safe step to the root's box (reading
// outsideBoundParams from slot Program::params.size() on), the ground unioned
// in exactly when the scene has one; result in Program::result. The box
// carries the default material (MATERIAL_SLOT), which
// Program::materialReads checks with the instructions' own.
std::vector<program::Instruction> outsideBoundCode(const program::Program& program);
std::vector<glm::dvec4> outsideBoundParams(const program::Program& program);
inline constexpr int kOutsideBoundSlots = 4;

// Builds it without the cache; tests lower `minInstructions` to prune small scenes.
std::shared_ptr<const PruneGrid> buildPruneGrid(const program::Program& program,
                                                int minInstructions = kMinPrunedInstructions);

// The leaf whose instructions evaluate the field at march point p, computed in
// the precision of p by the shared lookup the GLSL backend runs.
template <typename Vec3>
int leafIndexAt(const PruneGrid& grid, Vec3 p) {
    if constexpr (sizeof(typename Vec3::value_type) == sizeof(float)) {
        return lookup32::LeafLookup{grid.nodes.data()}.pruneLeafAt(p, lookup32::vec4(grid.lookupFrame()),
                                                                   lookup32::vec4(grid.lookupDims()));
    } else {
        return lookup64::LeafLookup{grid.nodes.data()}.pruneLeafAt(p, lookup64::vec4(grid.lookupFrame()),
                                                                   lookup64::vec4(grid.lookupDims()));
    }
}

}  // namespace sdfwb::prune
