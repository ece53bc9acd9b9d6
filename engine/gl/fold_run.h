#pragma once
// A group of many children compiles to one block of instructions repeated
// once per child (compileScene: child j's point transform and shape, then
// the group's boolean folding it into one accumulator), the copies differing
// only in their parameter and material slots, by a fixed stride per
// instruction. The GL backend emits such a run once, inside a loop over the
// children that the point's prune-grid cell keeps (docs/large-scenes.md):
// llvmpipe saves work only by running a loop fewer times, and the compile
// cost no longer grows with the number of children.

#include <optional>
#include <vector>

#include "program/program.h"
#include "prune/prune_grid.h"

namespace sdfwb::gl {

struct FoldRun {
    int start = 0;   // first instruction of block 0
    int length = 0;  // instructions per block
    int count = 0;   // blocks
    // per instruction of the block: slot of block j = slot of block 0 + stride * j
    std::vector<int> paramStride;
    std::vector<int> materialStride;
    int shape = 0;  // the block's shape instruction (its parameter slot names the child)
};

// Runs shorter than this stay straight-line code.
inline constexpr int kMinFoldBlocks = 16;
// Blocks per iteration of the fold loop: fewer loop back-edges against
// llvmpipe's limiter; the last iteration's unused copies are masked.
inline constexpr int kFoldUnroll = 16;

// The program's longest run of at least kMinFoldBlocks blocks whose skipping
// is exact: each block ends in a union or smooth union into one accumulator,
// its other registers are not read after the run, and the accumulator flows
// only into unions (a union of fewer children is never smaller, so wherever
// the grid dropped the group it stays dropped). Or none.
std::optional<FoldRun> findFoldRun(const program::Program& program);

// Per leaf of `grid` (null: one cell holding every block, as --no-prune),
// which blocks of `run` its pruned instructions keep: spans[leaf] = (first,
// count) into `blocks`. The outside leaf keeps none.
struct FoldLists {
    std::vector<int> nodes;  // the grid's, or one leaf
    std::vector<int> spans;  // 2 per leaf
    std::vector<int> blocks;
    int longest = 0;
};
FoldLists foldLists(const program::Program& program, const FoldRun& run, const prune::PruneGrid* grid);

}  // namespace sdfwb::gl
