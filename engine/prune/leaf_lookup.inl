// The shared cell lookup (sdf/glsl/prune_lookup.glsl) over a grid's nodes,
// included by prune_grid.h once per precision inside a namespace that has
// `using namespace sdfwb::sdf::f32` (or f64) in effect. No include guard.
struct LeafLookup {
    const int* nodes;

    int PN(int i) const { return nodes[static_cast<size_t>(i)]; }

#include "sdf/glsl/prune_lookup.glsl"
};
