// Large scenes (issue 10): per-pixel cost of the CPU backend with and without
// pruning, and with distance-only evaluation off, on the molecule and its
// subsets, its hard-union variant and generated scenes; the grid's build
// time and size; the GL backend (fold loops) on the molecules. Ratios are what to quote
// (docs/large-scenes.md): run niced, all in one run.
// Run: nice build/tests/bench/large_scene_bench  (sets MESA_SHADER_CACHE_DISABLE=true itself)

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <cstdlib>
#include <functional>
#include <utility>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "cpu/cpu_renderer.h"
#include "gl/gl_renderer.h"
#include "glcontext/osmesa_context.h"
#include "program/compile_scene.h"
#include "prune/prune_grid.h"
#include "scene/scene_json.h"
#include "support/large_scenes.h"
#include "support/scene_files.h"

namespace sdfwb {
namespace {

constexpr int kWidth = 160, kHeight = 90;

struct Case {
    const char* name;
    std::function<scene::Scene()> make;
};

const std::vector<Case>& cases() {
    static const std::vector<Case> all = {
        {"molecule_10", [] { return test::moleculeScene("molecule_10"); }},
        {"molecule_100", [] { return test::moleculeScene("molecule_100"); }},
        {"molecule_1001", [] { return test::moleculeScene("molecule"); }},
        {"molecule_hard_10", [] { return test::hardVariant(test::moleculeScene("molecule_10")); }},
        {"molecule_hard_100", [] { return test::hardVariant(test::moleculeScene("molecule_100")); }},
        {"molecule_hard_1001", [] { return test::hardVariant(test::moleculeScene("molecule")); }},
        {"city_10", [] { return test::cityScene(10); }},
        {"city_100", [] { return test::cityScene(100); }},
        {"city_1000", [] { return test::cityScene(1000); }},
        {"capsules_1000", [] { return test::capsuleChainScene(1000); }},
        {"nested_10", [] { return test::nestedGroupsScene(2, 5); }},
        {"nested_1000", [] { return test::nestedGroupsScene(64, 16); }},
    };
    return all;
}

program::Program compiled(int index, bool prune) {
    return program::compileScene(cases()[static_cast<size_t>(index)].make(),
                                 {.width = kWidth, .height = kHeight, .aa = 1, .prune = prune});
}

// CPU render time per pixel, the grid built beforehand (a GUI reuses it
// across progressive passes); range(1): 1 pruned, 0 the whole program, 2
// pruned with materials carried through every evaluation (distance-only
// evaluation off).
enum CpuMode { kWhole = 0, kPruned = 1, kPrunedMaterials = 2 };
void BM_Cpu(benchmark::State& state) {
    const auto mode = static_cast<CpuMode>(state.range(1));
    program::Program p = compiled(static_cast<int>(state.range(0)), mode != kWhole);
    p.distanceOnlyEvaluation = mode != kPrunedMaterials;
    std::shared_ptr<const prune::PruneGrid> grid = prune::pruneGridFor(p);
    for (auto _ : state) {
        benchmark::DoNotOptimize(cpu::renderCpu(p));
    }
    const char* modeName = mode == kWhole ? " whole" : mode == kPruned ? " pruned" : " materials";
    state.SetLabel(std::string(cases()[static_cast<size_t>(state.range(0))].name) + modeName + " " +
                   std::to_string(p.code.size()) + " instructions");
    state.counters["s_per_px"] = benchmark::Counter(kWidth * kHeight, benchmark::Counter::kIsIterationInvariantRate |
                                                                          benchmark::Counter::kInvert);
}

void BM_GridBuild(benchmark::State& state) {
    program::Program p = compiled(static_cast<int>(state.range(0)), true);
    std::shared_ptr<const prune::PruneGrid> grid;
    for (auto _ : state) {
        grid = prune::buildPruneGrid(p);
    }
    state.SetLabel(cases()[static_cast<size_t>(state.range(0))].name);
    if (grid) {
        long cells = 0, listed = 0;  // cells share equal leaves
        for (int node : grid->nodes) {
            if (node < 0) continue;
            ++cells;
            listed += grid->leaves[static_cast<size_t>(node)].count;
        }
        state.counters["cells"] = static_cast<double>(cells);
        state.counters["leaves"] = static_cast<double>(grid->leaves.size());
        state.counters["stored_instr"] = static_cast<double>(grid->code.size());
        state.counters["longest_leaf"] = grid->longestLeaf;
        state.counters["mean_cell"] = static_cast<double>(listed) / static_cast<double>(cells);
        state.counters["MB"] = static_cast<double>(grid->code.size() * sizeof(program::Instruction) +
                                                   grid->nodes.size() * sizeof(int) +
                                                   grid->leaves.size() * sizeof(prune::PruneLeaf)) / 1e6;
    }
}

// What an edit costs the grid, each iteration a new value: a colour edit
// finds the grid in the cache, a moved primitive builds it again
// (range(1): 0 a material's diffuse colour, 1 a translation).
void BM_GridAfterEdit(benchmark::State& state) {
    program::Program p = compiled(static_cast<int>(state.range(0)), true);
    prune::pruneGridFor(p);
    bool colour = state.range(1) == 0;
    auto edited = std::find_if(p.code.begin(), p.code.end(), [&](const program::Instruction& in) {
        return colour ? in.material >= 0 : in.op == program::Opcode::Translate && in.param >= 0;
    });
    glm::dvec4& value = p.params[static_cast<size_t>(colour ? edited->material + 1 : edited->param)];
    for (auto _ : state) {
        value.x += 1.0 / 1024.0;
        benchmark::DoNotOptimize(prune::pruneGridFor(p));
    }
    state.SetLabel(std::string(cases()[static_cast<size_t>(state.range(0))].name) + (colour ? " colour" : " move"));
}

glcontext::OsMesaContext& context() {
    static auto c = glcontext::OsMesaContext::create();
    return *c;
}

// Wall time of `work`.
double secondsOf(const std::function<void()>& work) {
    auto start = std::chrono::steady_clock::now();
    work();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// GL: the grid (built apart, as the window does on a background thread),
// the program's build (generation, compile, link and the first draw, where
// llvmpipe compiles the shader to machine code), then the time of a second
// render. range(1): 1 distance-only evaluations where they do, 0 materials
// carried through every evaluation.
void BM_Gl(benchmark::State& state) {
    program::Program p = compiled(static_cast<int>(state.range(0)), true);
    p.distanceOnlyEvaluation = state.range(1) != 0;
    double grid = secondsOf([&] { prune::pruneGridFor(p); });
    gl::GlRenderer renderer(context().gl());
    double build = 0;
    try {
        build = secondsOf([&] {
            renderer.prepare(p);
            renderer.render(p);
        });
    } catch (const std::exception& refused) {
        // over the size bound: the CPU backend stands in
        state.SkipWithError(refused.what());
        return;
    }
    for (auto _ : state) {
        benchmark::DoNotOptimize(renderer.render(p));
    }
    state.SetLabel(std::string(cases()[static_cast<size_t>(state.range(0))].name) +
                   (p.distanceOnlyEvaluation ? "" : " materials"));
    state.counters["grid_s"] = grid;
    state.counters["build_s"] = build;
    state.counters["s_per_px"] = benchmark::Counter(kWidth * kHeight, benchmark::Counter::kIsIterationInvariantRate |
                                                                          benchmark::Counter::kInvert);
}

void cpuArgs(benchmark::internal::Benchmark* b) {
    for (int i = 0; i < static_cast<int>(cases().size()); ++i) {
        b->Args({i, kPruned});
        b->Args({i, kWhole});
        b->Args({i, kPrunedMaterials});
    }
}
BENCHMARK(BM_Cpu)->Apply(cpuArgs)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);
BENCHMARK(BM_GridBuild)->DenseRange(0, 11)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);
BENCHMARK(BM_GridAfterEdit)
    ->ArgsProduct({{1, 2, 9}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(3);
// The CPU backend against GL on every shipped scene: per scene the time of a
// CPU render (the grid, if any, built first) over that of GL's second render,
// at the same size; the median, the extremes and how many scenes the CPU
// renders faster, and the label names the scenes at the extremes. The
// scenes' own settings at 160x90, AA 1; range(0) = 0 turns the CPU's
// distance-only evaluation off.
void BM_SceneSuiteCpuOverGl(benchmark::State& state) {
    std::vector<std::pair<double, std::string>> ratios;  // CPU over GL, scene
    for (auto _ : state) {
        for (const test::SceneFile& file : test::allSceneFiles()) {
            program::Program p = program::compileScene(scene::loadSceneFile(file.path()),
                                                       {.width = kWidth, .height = kHeight, .aa = 1});
            p.distanceOnlyEvaluation = state.range(0) != 0;
            prune::pruneGridFor(p);
            gl::GlRenderer renderer(context().gl());
            renderer.prepare(p);
            renderer.render(p);
            double gl = secondsOf([&] { renderer.render(p); });
            double cpu = secondsOf([&] { cpu::renderCpu(p); });
            ratios.emplace_back(cpu / gl, file.relative);
        }
    }
    std::sort(ratios.begin(), ratios.end());
    auto named = [](const std::pair<double, std::string>& ratio) {
        char figure[32];
        std::snprintf(figure, sizeof figure, " %.2f", ratio.first);
        return ratio.second + figure;
    };
    state.SetLabel(std::string(state.range(0) != 0 ? "distance-only" : "materials everywhere") + "; min " +
                   named(ratios.front()) + ", max " + named(ratios.back()));
    state.counters["scenes"] = static_cast<double>(ratios.size());
    state.counters["median"] = ratios[ratios.size() / 2].first;
    state.counters["min"] = ratios.front().first;
    state.counters["max"] = ratios.back().first;
    state.counters["cpu_faster"] = static_cast<double>(
        std::count_if(ratios.begin(), ratios.end(), [](const auto& ratio) { return ratio.first < 1.0; }));
}
BENCHMARK(BM_SceneSuiteCpuOverGl)->Arg(1)->Arg(0)->Unit(benchmark::kSecond)->UseRealTime()->Iterations(1);

// the molecules on GL (fold loops)
BENCHMARK(BM_Gl)
    ->ArgsProduct({benchmark::CreateDenseRange(0, 5, 1), {1, 0}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1);

// The console table, then the per-pixel cost ratios the docs quote, all from
// this run: 100 / 10 and 1001 / 10 for each backend and scene family, and
// the CPU backend (pruned) against GL where GL builds.
class RatioReporter : public benchmark::ConsoleReporter {
public:
    void ReportRuns(const std::vector<Run>& runs) override {
        ConsoleReporter::ReportRuns(runs);
        for (const Run& run : runs) {
            auto cost = run.counters.find("s_per_px");
            if (run.error_occurred || cost == run.counters.end()) continue;
            std::string label = run.report_label, scene = label.substr(0, label.find(' '));
            std::string mode;
            for (const char* name : {" pruned", " whole", " materials"}) {
                if (label.find(name) != std::string::npos) mode = name;
            }
            costs_[run.run_name.function_name + mode + " " + scene] = cost->second.value;
        }
    }

    void Finalize() override {
        ConsoleReporter::Finalize();
        auto ratio = [&](const std::string& a, const std::string& b) {
            auto x = costs_.find(a), y = costs_.find(b);
            return x == costs_.end() || y == costs_.end() ? std::string("-") : std::to_string(x->second / y->second);
        };
        std::printf("\nper-pixel cost ratios (this run)\n%-16s %-18s %12s %12s\n", "backend", "scenes", "100/10",
                    "1001/10");
        for (const char* backend : {"BM_Cpu pruned", "BM_Cpu whole", "BM_Gl"}) {
            for (const auto& [family, large] : {std::pair<std::string, std::string>{"molecule", "1001"},
                                                {"molecule_hard", "1001"},
                                                {"city", "1000"}}) {
                std::string base = std::string(backend) + " " + family + "_";
                std::printf("%-16s %-18s %12s %12s\n", backend, family.c_str(),
                            ratio(base + "100", base + "10").c_str(), ratio(base + large, base + "10").c_str());
            }
        }
        std::printf("\nCPU: materials at every evaluation / distance-only evaluation, per pixel\n");
        for (const Case& c : cases()) {
            std::printf("%-18s %12s\n", c.name,
                        ratio(std::string("BM_Cpu materials ") + c.name, std::string("BM_Cpu pruned ") + c.name).c_str());
        }
        std::printf("\nGL: materials at every evaluation / distance-only evaluation, per pixel\n");
        for (const Case& c : cases()) {
            std::string r = ratio(std::string("BM_Gl materials ") + c.name, std::string("BM_Gl ") + c.name);
            if (r != "-") std::printf("%-18s %12s\n", c.name, r.c_str());  // BM_Gl covers the molecules
        }
        std::printf("\nCPU pruned / GL per pixel (GL's second render)\n");
        for (const char* scene : {"molecule_10", "molecule_100", "molecule_hard_10", "molecule_hard_100"}) {
            std::printf("%-18s %12s\n", scene,
                        ratio(std::string("BM_Cpu pruned ") + scene, std::string("BM_Gl ") + scene).c_str());
        }
    }

private:
    std::map<std::string, double> costs_;
};

}  // namespace
}  // namespace sdfwb

int main(int argc, char** argv) {
    setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);
    benchmark::Initialize(&argc, argv);
    sdfwb::RatioReporter reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);
    benchmark::Shutdown();
    return 0;
}
