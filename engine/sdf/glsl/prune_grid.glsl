// The layout of a prune grid (engine/prune/prune_grid.h), which both
// backends read: a split cell has PRUNE_SPLIT^3 children, and cells split at
// most PRUNE_MAX_DEPTH times below a root cell (prune_lookup.glsl descends
// that many levels, unrolled).
const int PRUNE_SPLIT = 2;
const int PRUNE_MAX_DEPTH = 5;
