// Which leaf of a prune grid (engine/prune/prune_grid.h) holds the
// instructions for march point p: the same float operations in both backends
// and in every precision, so both evaluate the same leaf. The backend supplies
// PN(i), node i of the grid (>= 0: a leaf; < 0: -(first child + 1)), as it
// supplies P and map to sample_driver.glsl. frame = (the grid's origin,
// 1 / root cell size), dims = (root cells per axis, the leaf outside the grid).

// One level down: q - floor(q) is exact in floating point, so the split is too.
SHARED_FN int pruneChild(int node, vec3 cell) {
    return PN(-node - 1 + int(cell.x) + PRUNE_SPLIT * (int(cell.y) + PRUNE_SPLIT * int(cell.z)));
}

SHARED_FN int pruneLeafAt(vec3 p, vec4 frame, vec4 dims) {
    vec3 q = (p - xyz(frame)) * frame.w;
    if (!(q.x >= real(0) && q.y >= real(0) && q.z >= real(0) && q.x < dims.x && q.y < dims.y && q.z < dims.z)) {
        return int(dims.w);
    }
    vec3 cell = floor(q);
    int node = PN(int(cell.x) + int(dims.x) * (int(cell.y) + int(dims.y) * int(cell.z)));
    // PRUNE_MAX_DEPTH levels, unrolled: llvmpipe counts every loop's
    // back-edges against one limit per invocation (docs/toolchain-notes.md)
    if (node < 0) {
        q = (q - cell) * real(PRUNE_SPLIT);
        cell = floor(q);
        node = pruneChild(node, cell);
    }
    if (node < 0) {
        q = (q - cell) * real(PRUNE_SPLIT);
        cell = floor(q);
        node = pruneChild(node, cell);
    }
    if (node < 0) {
        q = (q - cell) * real(PRUNE_SPLIT);
        cell = floor(q);
        node = pruneChild(node, cell);
    }
    if (node < 0) {
        q = (q - cell) * real(PRUNE_SPLIT);
        cell = floor(q);
        node = pruneChild(node, cell);
    }
    if (node < 0) {
        q = (q - cell) * real(PRUNE_SPLIT);
        cell = floor(q);
        node = pruneChild(node, cell);
    }
    return node;
}
