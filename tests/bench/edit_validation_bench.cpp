// What validating one edit costs (issue 9): the old way, writing the scene as
// JSON and reading it back, against the model validator with its remembered
// formula verdicts, as the editor runs it after each slider frame.
//   build/tests/bench/edit_validation_bench
#include <benchmark/benchmark.h>

#include "scene/scene_json.h"
#include "scene/scene_validation.h"
#include "support/source_tree.h"

namespace {

using namespace sdfwb;

const char* const kScenes[] = {"scenes/showcase/implicitized_classics.json", "scenes/hard/enneper_degree9.json",
                               "scenes/default.json", "tests/data/large/molecule.json"};

scene::Scene load(int index) { return scene::loadSceneFile(test::sourceDir() + "/" + kScenes[index]); }

void BM_JsonRoundTrip(benchmark::State& state) {
    scene::Scene scene = load(static_cast<int>(state.range(0)));
    for (auto _ : state) {
        try {
            benchmark::DoNotOptimize(scene::sceneFromJson(scene::sceneToJson(scene)));
        } catch (const scene::SceneError&) {
            state.SkipWithError("invalid scene");
        }
    }
    state.SetLabel(kScenes[state.range(0)]);
}

void BM_ModelValidation(benchmark::State& state) {
    scene::Scene scene = load(static_cast<int>(state.range(0)));
    scene::FormulaVerdicts verdicts;
    scene::validateScene(scene, &verdicts);  // the editor's verdicts are warm after the first edit
    for (auto _ : state) benchmark::DoNotOptimize(scene::validateScene(scene, &verdicts));
    state.SetLabel(kScenes[state.range(0)]);
}

BENCHMARK(BM_JsonRoundTrip)->DenseRange(0, 3)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ModelValidation)->DenseRange(0, 3)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
