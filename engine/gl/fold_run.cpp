#include "gl/fold_run.h"

#include <algorithm>
#include <unordered_map>

namespace sdfwb::gl {

using program::Instruction;
using program::OpClass;
using program::opcodeInfo;

namespace {

bool sameShape(const Instruction& x, const Instruction& y) {
    return x.op == y.op && x.dst == y.dst && x.a == y.a && x.b == y.b && x.variant == y.variant &&
           (x.param < 0) == (y.param < 0) && (x.material < 0) == (y.material < 0);
}

// Blocks of `length` from `start` that repeat block 0 with constant slot strides.
int blocksFrom(const std::vector<Instruction>& code, int start, int length, FoldRun& run) {
    int n = static_cast<int>(code.size());
    if (start + 2 * length > n) return 1;
    run.paramStride.assign(static_cast<size_t>(length), 0);
    run.materialStride.assign(static_cast<size_t>(length), 0);
    for (int i = 0; i < length; ++i) {
        const Instruction &x = code[static_cast<size_t>(start + i)], &y = code[static_cast<size_t>(start + length + i)];
        if (!sameShape(x, y)) return 1;
        run.paramStride[static_cast<size_t>(i)] = x.param < 0 ? 0 : y.param - x.param;
        run.materialStride[static_cast<size_t>(i)] = x.material < 0 ? 0 : y.material - x.material;
    }
    int blocks = 2;
    for (; start + (blocks + 1) * length <= n; ++blocks) {
        for (int i = 0; i < length; ++i) {
            const Instruction &x = code[static_cast<size_t>(start + i)],
                              &y = code[static_cast<size_t>(start + blocks * length + i)];
            if (!sameShape(x, y) || (x.param >= 0 && y.param != x.param + blocks * run.paramStride[static_cast<size_t>(i)]) ||
                (x.material >= 0 && y.material != x.material + blocks * run.materialStride[static_cast<size_t>(i)])) {
                return blocks;
            }
        }
    }
    return blocks;
}

// Skipping a block is exact when it is "temporaries, then acc = op(acc, t)":
// one shape, naming the child by a parameter slot that moves, and nothing
// but the accumulator read after the run from what the blocks write.
bool skippable(const program::Program& program, const FoldRun& run) {
    const auto& code = program.code;
    const Instruction& last = code[static_cast<size_t>(run.start + run.length - 1)];
    if ((last.op != program::Opcode::Union && last.op != program::Opcode::SmoothUnion) || last.dst != last.a) {
        return false;
    }
    int shapes = 0;
    for (int i = 0; i < run.length; ++i) {
        const Instruction& in = code[static_cast<size_t>(run.start + i)];
        if (program::isShapeClass(opcodeInfo(in.op).opClass)) {
            ++shapes;
            if (run.paramStride[static_cast<size_t>(i)] == 0 || in.param < 0) return false;
        }
        if (i + 1 < run.length && opcodeInfo(in.op).opClass != OpClass::Point && in.dst == last.dst) return false;
    }
    if (shapes != 1) return false;
    // temporaries written by the blocks must be written again before any later read
    std::vector<bool> pointTemp(static_cast<size_t>(program.pointRegisters)),
        sampleTemp(static_cast<size_t>(program.sampleRegisters));
    for (int i = 0; i + 1 < run.length; ++i) {
        const Instruction& in = code[static_cast<size_t>(run.start + i)];
        (opcodeInfo(in.op).opClass == OpClass::Point ? pointTemp : sampleTemp)[static_cast<size_t>(in.dst)] = true;
    }
    for (size_t k = static_cast<size_t>(run.start + run.length * run.count); k < code.size(); ++k) {
        const Instruction& in = code[k];
        OpClass c = opcodeInfo(in.op).opClass;
        bool pointA = c == OpClass::Point || program::isShapeClass(c) || c == OpClass::FormulaShape ||
                      c == OpClass::FormulaSample || c == OpClass::ShapeSample;
        if (pointA && in.a >= 0 && pointTemp[static_cast<size_t>(in.a)]) return false;
        if (!pointA && c != OpClass::Constant && in.a >= 0 && sampleTemp[static_cast<size_t>(in.a)]) return false;
        if (program::isCombineClass(c) && sampleTemp[static_cast<size_t>(in.b)]) return false;
        bool pointB = c == OpClass::Post || c == OpClass::Texture || c == OpClass::ImageTexture ||
                      c == OpClass::FormulaImageTexture;
        if (pointB && pointTemp[static_cast<size_t>(in.b)]) return false;
        (c == OpClass::Point ? pointTemp : sampleTemp)[static_cast<size_t>(in.dst)] = false;
    }
    // Skipping blocks leaves the accumulator at least its whole value (a union
    // of fewer children is never smaller): exact where the grid dropped it
    // only if everything it flows into is a union too (an intersection or a
    // difference would let the larger value lose where it must not).
    std::vector<bool> tainted(static_cast<size_t>(program.sampleRegisters));
    tainted[static_cast<size_t>(last.dst)] = true;
    for (size_t k = static_cast<size_t>(run.start + run.length * run.count); k < code.size(); ++k) {
        const Instruction& in = code[k];
        OpClass c = opcodeInfo(in.op).opClass;
        bool readsA = c == OpClass::Combine || c == OpClass::SmoothCombine || c == OpClass::Post;
        bool reads = (readsA && tainted[static_cast<size_t>(in.a)]) ||
                     (program::isCombineClass(c) && tainted[static_cast<size_t>(in.b)]);
        bool unionLike = in.op == program::Opcode::Union || in.op == program::Opcode::SmoothUnion;
        if (reads && !unionLike) return false;
        if (c != OpClass::Point) tainted[static_cast<size_t>(in.dst)] = reads;
    }
    return true;
}

}  // namespace

std::optional<FoldRun> findFoldRun(const program::Program& program) {
    const auto& code = program.code;
    int n = static_cast<int>(code.size());
    std::optional<FoldRun> best;
    constexpr int kMaxBlockLength = 8;
    for (int length = 1; length <= kMaxBlockLength; ++length) {
        for (int start = 0; start + length * kMinFoldBlocks <= n;) {
            FoldRun run;
            run.start = start;
            run.length = length;
            run.count = blocksFrom(code, start, length, run);
            if (run.count >= kMinFoldBlocks) {
                for (int i = 0; i < length; ++i) {
                    if (program::isShapeClass(opcodeInfo(code[static_cast<size_t>(start + i)].op).opClass)) run.shape = i;
                }
                if (skippable(program, run) && (!best || run.count * run.length > best->count * best->length)) {
                    best = run;
                }
                start += run.count * length;
            } else {
                ++start;
            }
        }
    }
    return best;
}

FoldLists foldLists(const program::Program& program, const FoldRun& run, const prune::PruneGrid* grid) {
    FoldLists lists;
    const Instruction& shape = program.code[static_cast<size_t>(run.start + run.shape)];
    int stride = run.paramStride[static_cast<size_t>(run.shape)];
    if (grid == nullptr) {
        lists.nodes = {0};
        lists.spans = {0, run.count, 0, 0};  // leaf 0: every block; leaf 1 (outside): none
        for (int j = 0; j < run.count; ++j) lists.blocks.push_back(j);
        lists.longest = run.count;
        return lists;
    }
    lists.nodes = grid->nodes;
    for (size_t leaf = 0; leaf < grid->leaves.size(); ++leaf) {
        const prune::PruneLeaf& l = grid->leaves[leaf];
        int first = static_cast<int>(lists.blocks.size());
        if (static_cast<int>(leaf) != grid->outsideLeaf) {
            for (int k = l.offset; k < l.offset + l.count; ++k) {
                const Instruction& in = grid->code[static_cast<size_t>(k)];
                if (in.op != shape.op || in.param < shape.param) continue;
                int offset = in.param - shape.param;
                if (offset % stride == 0 && offset / stride < run.count) lists.blocks.push_back(offset / stride);
            }
        }
        int count = static_cast<int>(lists.blocks.size()) - first;
        // in the program's order, as the whole program folds them
        std::sort(lists.blocks.begin() + first, lists.blocks.end());
        lists.spans.push_back(first);
        lists.spans.push_back(count);
        lists.longest = std::max(lists.longest, count);
    }
    return lists;
}

}  // namespace sdfwb::gl
