#include "prune/prune_grid.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <condition_variable>
#include <cstring>
#include <deque>
#include <mutex>
#include <optional>
#include <set>
#include <span>
#include <string_view>
#include <type_traits>
#include <unordered_map>

#include "jobs/job_queue.h"
#include "jobs/parallel_for.h"
#include "prune/cell_pruning.h"
#include "sdf/shared.h"

namespace sdfwb::prune {

using program::Instruction;
using program::Opcode;

namespace {

// Root cells across the grid's longest side.
constexpr int kRootCells = 8;
// A cell is split while its list is longer than this.
constexpr int kLeafTarget = 32;
// Lights softer than this would need too wide a grid (gridMargin).
constexpr double kMinSoftness = 1.25;
// A split is kept when its children average at most this fraction of the
// cell's instructions.
constexpr double kSplitGain = 0.75;
// Instructions over all leaves at most, counted as each cell's list is added
// (the children of a split that prune nothing more count once), before equal
// lists are shared (LeafStore): it bounds the build's work.
constexpr long kCodeBudget = 4000000;

// Leaves and their instructions, each distinct list stored once. Neighbouring
// cells far from the surface keep the same children, so most leaves repeat
// others (docs/large-scenes.md, "Shared leaves": a 35x smaller grid for the
// 100-sphere molecule).
class LeafStore {
public:
    // The index of a leaf holding `list` with its field in `result`.
    int add(std::span<const Instruction> list, int result) {
        const std::string_view bytes = bytesOf(list);
        const std::size_t key = std::hash<std::string_view>{}(bytes) ^ static_cast<std::size_t>(result);
        auto [first, last] = index_.equal_range(key);
        for (auto it = first; it != last; ++it) {
            const PruneLeaf& leaf = leaves[static_cast<size_t>(it->second)];
            if (leaf.result == result && bytesOf(listOf(leaf)) == bytes) return it->second;
        }
        const int added = static_cast<int>(leaves.size());
        leaves.push_back({static_cast<int>(code.size()), static_cast<int>(list.size()), result});
        code.insert(code.end(), list.begin(), list.end());
        index_.emplace(key, added);
        return added;
    }

    std::span<const Instruction> listOf(const PruneLeaf& leaf) const {
        return {code.data() + leaf.offset, static_cast<size_t>(leaf.count)};
    }

    std::vector<PruneLeaf> leaves;
    std::vector<Instruction> code;

private:
    static std::string_view bytesOf(std::span<const Instruction> list) {
        static_assert(std::has_unique_object_representations_v<Instruction>, "instructions compare by their bytes");
        return {reinterpret_cast<const char*>(list.data()), list.size_bytes()};
    }

    std::unordered_multimap<std::size_t, int> index_;
};

// One root cell's subtree, indices local to it until merged.
struct LocalTree {
    std::vector<int> nodes{0};  // nodes[0]: the root cell
    LeafStore leaves;
};

class Builder {
public:
    explicit Builder(const program::Program& program) : program_(program) {}

    void buildRoot(LocalTree& tree, const CodeSpan& full, glm::dvec3 lo, double size) {
        CellPruner pruner(program_);
        tree.nodes[0] = build(pruner, tree, prunedFor(pruner, full, lo, size), lo, size, 0);
    }

private:
    static CodeSpan prunedFor(CellPruner& pruner, const CodeSpan& parent, glm::dvec3 lo, double size) {
        glm::dvec3 centre = lo + glm::dvec3(0.5 * size);
        // the half diagonal, widened for points the float cell lookup files
        // here from just outside
        double radius = 0.5 * std::sqrt(3.0) * size * (1.0 + 1e-4) + 1e-6 * glm::length(centre);
        return pruner.prune(parent, centre, radius);
    }

    int addLeaf(LocalTree& tree, const CodeSpan& span) {
        stored_ += static_cast<long>(span.code.size());
        return tree.leaves.add(span.code, span.result);
    }

    // `pruned` is already pruned for this cell. The cell splits only where
    // its children are markedly shorter on average, so the work and memory
    // go where the scene is dense.
    int build(CellPruner& pruner, LocalTree& tree, const CodeSpan& pruned, glm::dvec3 lo, double size, int depth) {
        int count = static_cast<int>(pruned.code.size());
        if (count <= kLeafTarget || depth >= kMaxDepth || stored_ > kCodeBudget) {
            return addLeaf(tree, pruned);
        }
        constexpr int kChildren = kSplit * kSplit * kSplit;
        double child = size / kSplit;
        std::vector<CodeSpan> children(kChildren);
        long total = 0;
        for (int j = 0; j < kChildren; ++j) {
            glm::dvec3 offset(j % kSplit, (j / kSplit) % kSplit, j / (kSplit * kSplit));
            children[static_cast<size_t>(j)] = prunedFor(pruner, pruned, lo + offset * child, child);
            total += static_cast<long>(children[static_cast<size_t>(j)].code.size());
        }
        if (static_cast<double>(total) > kSplitGain * kChildren * count) {
            return addLeaf(tree, pruned);
        }
        size_t first = tree.nodes.size();
        tree.nodes.resize(first + kChildren);
        int unpruned = -1;  // one leaf for the children that prune nothing more
        for (int j = 0; j < kChildren; ++j) {
            glm::dvec3 offset(j % kSplit, (j / kSplit) % kSplit, j / (kSplit * kSplit));
            const CodeSpan& span = children[static_cast<size_t>(j)];
            int node = 0;
            if (span.code.size() == pruned.code.size()) {
                node = unpruned = unpruned >= 0 ? unpruned : addLeaf(tree, pruned);
            } else {
                node = build(pruner, tree, span, lo + offset * child, child, depth + 1);
            }
            tree.nodes[first + static_cast<size_t>(j)] = node;
        }
        return -static_cast<int>(first) - 1;
    }

    const program::Program& program_;
    std::atomic<long> stored_{0};
};

// compileScene unions the ground plane last: its block (the Ground
// instruction, its texture's, if any) from Program::groundStart, then
// Union(result, ground).
bool endsWithGround(const program::Program& program) {
    size_t n = program.code.size(), start = static_cast<size_t>(program.groundStart);
    if (program.groundStart < 0 || start + 2 > n) return false;
    // the ground's world point first when it is textured
    size_t ground = program.code[start].op == Opcode::Translate ? start + 1 : start;
    return ground + 1 < n && program.code[ground].op == Opcode::Ground && program.code[n - 1].op == Opcode::Union &&
           program.code[n - 1].a == program.result && program.code[n - 1].b == program.code[ground].dst;
}

// Outside the grid the field is replaced by a safe step, the distance to the
// root's box, with a distance channel 2^20 times that: no hit, no penumbra,
// no occlusion comes from out there (the margin makes that hold for the real
// field too, see gridMargin), and the ground is unioned in exactly.
constexpr double kOutsideDistanceScale = 1048576.0;  // a power of two: step = box distance exactly

void addOutsideLeaf(const program::Program& program, PruneGrid& grid) {
    std::vector<Instruction> code = outsideBoundCode(program);
    grid.extraParams = outsideBoundParams(program);
    grid.outsideLeaf = static_cast<int>(grid.leaves.size());
    grid.leaves.push_back({static_cast<int>(grid.code.size()), static_cast<int>(code.size()), program.result});
    grid.code.insert(grid.code.end(), code.begin(), code.end());
    // pruneLeafAt's arguments, for a backend reading them from its parameter buffer
    grid.extraParams.push_back(grid.lookupFrame());
    grid.extraParams.push_back(grid.lookupDims());
}

// How far the grid reaches beyond the root's box. A shadow ray from a surface
// at distance t, outside the grid, is at least the margin M from the surface
// and t <= M' + D (D the box's diagonal, M' >= M its distance to the box), so
// its penumbra term k d / t >= k M / (M + D) >= 1 for M = D / (k - 1): it
// never darkens anything, and ignoring it there is exact. Negative when no
// margin makes the shortcut exact (a light softer than that).
double gridMargin(const program::Program& program) {
    double diagonal = glm::length(program.rootMax - program.rootMin);
    double margin = std::max(0.25 * diagonal, 2.0 * program.trace.aoDistance);
    bool penumbrae = program.trace.shadowMode == sdf::f64::SHADOW_SOFT || program.trace.shadowMode == sdf::f64::SHADOW_IMPROVED;
    if (penumbrae) {
        for (const program::LightParams& light : program.lights) {
            if (!(light.softness > kMinSoftness)) return -1.0;
            margin = std::max(margin, diagonal / (light.softness - 1.0));
        }
    }
    return margin;
}

}  // namespace

std::vector<Instruction> outsideBoundCode(const program::Program& program) {
    int base = static_cast<int>(program.params.size());
    int r = program.result;
    std::vector<Instruction> code = {{Opcode::Translate, 1, 0, -1, base, -1, 0},
                                     {Opcode::Box, r, 1, -1, base + 1, sdf::f64::MATERIAL_SLOT, 0},
                                     {Opcode::ScaleDistance, r, r, 0, base + 2, -1, 0},
                                     {Opcode::StepScale, r, r, 0, base + 3, -1, 0}};
    if (endsWithGround(program)) {
        code.insert(code.end(), program.code.begin() + program.groundStart, program.code.end());
    }
    return code;
}

std::vector<glm::dvec4> outsideBoundParams(const program::Program& program) {
    glm::dvec3 centre = 0.5 * (program.rootMin + program.rootMax), half = 0.5 * (program.rootMax - program.rootMin);
    return {glm::dvec4(-centre, 0.0), glm::dvec4(half, 0.0), glm::dvec4(kOutsideDistanceScale, 0, 0, 0),
            glm::dvec4(1.0 / kOutsideDistanceScale, 0, 0, 0)};
}

std::shared_ptr<const PruneGrid> buildPruneGrid(const program::Program& program, int minInstructions) {
    // the outside bound needs a second point register
    if (!program.prune || !program.rootBounded || program.pointRegisters < 2 ||
        static_cast<int>(program.code.size()) < minInstructions) {
        return nullptr;
    }
    double margin = gridMargin(program);
    if (margin < 0.0) {
        return nullptr;
    }
    // the eye (the origin of march coordinates) inside too: primary rays start in exact cells
    glm::dvec3 lo = glm::min(program.rootMin - glm::dvec3(margin), glm::dvec3(-2.0 * program.trace.epsilon - 1e-3)),
               hi = glm::max(program.rootMax + glm::dvec3(margin), glm::dvec3(2.0 * program.trace.epsilon + 1e-3));
    glm::dvec3 extent = hi - lo;
    auto grid = std::make_shared<PruneGrid>();
    grid->cellSize = std::max(extent.x, std::max(extent.y, extent.z)) / kRootCells;
    grid->dims = glm::max(glm::ivec3(glm::ceil(extent / grid->cellSize)), glm::ivec3(1));
    grid->origin = lo;

    int roots = grid->dims.x * grid->dims.y * grid->dims.z;
    std::vector<LocalTree> trees(static_cast<size_t>(roots));
    CodeSpan full{program.code, program.result};
    Builder builder(program);
    jobs::parallelFor(roots, [&](int i) {
        glm::ivec3 cell(i % grid->dims.x, (i / grid->dims.x) % grid->dims.y, i / (grid->dims.x * grid->dims.y));
        builder.buildRoot(trees[static_cast<size_t>(i)], full, lo + glm::dvec3(cell) * grid->cellSize, grid->cellSize);
    });

    // merge: root cells first, then every tree's inner nodes; a leaf equal to
    // one of another tree is shared
    grid->nodes.resize(static_cast<size_t>(roots));
    LeafStore merged;
    bool saves = false;
    for (int i = 0; i < roots; ++i) {
        const LocalTree& tree = trees[static_cast<size_t>(i)];
        std::vector<int> leafIndex;
        for (const PruneLeaf& leaf : tree.leaves.leaves) {
            leafIndex.push_back(merged.add(tree.leaves.listOf(leaf), leaf.result));
            grid->longestLeaf = std::max(grid->longestLeaf, leaf.count);
            saves = saves || leaf.count < static_cast<int>(program.code.size());
        }
        int nodeBase = static_cast<int>(grid->nodes.size()) - 1;  // local node 1 lands at nodes.size()
        auto relocate = [&](int node) { return node >= 0 ? leafIndex[static_cast<size_t>(node)] : node - nodeBase; };
        grid->nodes[static_cast<size_t>(i)] = relocate(tree.nodes[0]);
        for (size_t n = 1; n < tree.nodes.size(); ++n) grid->nodes.push_back(relocate(tree.nodes[n]));
    }
    if (!saves) {
        return nullptr;
    }
    grid->leaves = std::move(merged.leaves);
    grid->code = std::move(merged.code);
    addOutsideLeaf(program, *grid);
    return grid;
}

namespace {

// What a grid depends on: the instructions, the parameter slots they read
// (materials, camera colours and lights are not among them: pruning decides
// on distances alone, and a leaf reads every parameter when it runs, so a
// colour edit keeps the grid), the bounds, what gridMargin reads and the switch.
std::uint64_t gridKey(const program::Program& program) {
    std::uint64_t hash = program.codeKey();
    auto mix = [&](const void* data, size_t size) {
        const unsigned char* bytes = static_cast<const unsigned char*>(data);
        for (size_t i = 0; i < size; ++i) {
            hash ^= bytes[i];
            hash *= 1099511628211ull;
        }
    };
    for (const Instruction& in : program.code) {
        if (in.param >= 0) {
            mix(program.params.data() + in.param, program::opcodeInfo(in.op).paramSlots * sizeof(glm::dvec4));
        }
    }
    mix(&program.rootMin, sizeof(program.rootMin));
    mix(&program.rootMax, sizeof(program.rootMax));
    const double trace[3] = {program.trace.aoDistance, program.trace.epsilon, double(program.trace.shadowMode)};
    mix(trace, sizeof(trace));
    for (const program::LightParams& light : program.lights) mix(&light.softness, sizeof(light.softness));
    unsigned char flags[2] = {program.rootBounded, program.prune};
    mix(flags, sizeof(flags));
    return hash;
}

std::atomic<long> gridsBuilt{0};

}  // namespace

long pruneGridsBuilt() { return gridsBuilt.load(); }

namespace {

// The grids built last, by gridKey; the keys a thread is building now (a
// second caller waits for that build instead of repeating it); the keys
// queued for a background build.
struct GridCache {
    std::mutex mutex;
    std::condition_variable built;
    std::deque<std::pair<std::uint64_t, std::shared_ptr<const PruneGrid>>> grids;
    std::set<std::uint64_t> building;
    std::set<std::uint64_t> queued;

    std::optional<std::shared_ptr<const PruneGrid>> find(std::uint64_t key) {
        for (const auto& entry : grids) {
            if (entry.first == key) return entry.second;
        }
        return std::nullopt;
    }
};

GridCache& gridCache() {
    static GridCache cache;
    return cache;
}

// Constructed after the cache (pruneGridIfBuilt asks the cache first), so
// destroyed before it: its last job still finds the cache.
jobs::JobQueue& backgroundBuilds() {
    static jobs::JobQueue queue(1);
    return queue;
}

}  // namespace

std::shared_ptr<const PruneGrid> pruneGridFor(const program::Program& program) {
    // progressive and tiled renders of one program ask for its grid many times
    constexpr size_t kCached = 4;
    GridCache& cache = gridCache();
    std::uint64_t key = gridKey(program);
    std::unique_lock lock(cache.mutex);
    while (true) {
        if (auto grid = cache.find(key)) return *grid;
        if (cache.building.insert(key).second) break;
        cache.built.wait(lock);
    }
    lock.unlock();
    std::shared_ptr<const PruneGrid> grid;
    try {
        grid = buildPruneGrid(program);
    } catch (...) {
        lock.lock();
        cache.building.erase(key);
        cache.built.notify_all();
        throw;
    }
    ++gridsBuilt;
    lock.lock();
    cache.grids.emplace_front(key, grid);
    if (cache.grids.size() > kCached) cache.grids.pop_back();
    cache.building.erase(key);
    cache.built.notify_all();
    return grid;
}

std::optional<std::shared_ptr<const PruneGrid>> pruneGridIfBuilt(const program::Program& program) {
    GridCache& cache = gridCache();
    std::uint64_t key = gridKey(program);
    {
        std::lock_guard lock(cache.mutex);
        if (auto grid = cache.find(key)) return grid;
        if (!cache.queued.insert(key).second) return std::nullopt;
    }
    auto copy = std::make_shared<program::Program>(program);
    backgroundBuilds().submit([copy, key](jobs::Job&) {
        pruneGridFor(*copy);
        GridCache& c = gridCache();
        std::lock_guard lock(c.mutex);
        c.queued.erase(key);
    });
    return std::nullopt;
}

}  // namespace sdfwb::prune
