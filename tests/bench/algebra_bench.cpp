// Our Groebner bases and implicitizations against Singular, measured in the
// same run. Each benchmark reports our time (the benchmark's own timing) and
// Singular's wall-clock time for the same command as the counter
// "singular_s"; "ratio" is ours / Singular's. Singular gets a timeout; a
// counter of -1 means it did not finish.
//
//   build/tests/bench/algebra_bench --benchmark_filter=katsura

#include "algebra/groebner.h"
#include "example_systems.h"
#include "singular_runner.h"

#include <benchmark/benchmark.h>

#include <functional>

namespace sdfwb::algebra {
namespace {

constexpr double kSingularTimeout = 120;

void report_singular(benchmark::State& state, const testing::SingularResult& singular, double ours_seconds) {
  state.counters["singular_s"] = singular.ok ? singular.seconds : -1;
  state.counters["ours_s"] = ours_seconds;
  if (singular.ok && singular.seconds > 0) state.counters["ratio"] = ours_seconds / singular.seconds;
}

void register_groebner(const std::string& name, std::function<Ideal()> make) {
  benchmark::RegisterBenchmark(("groebner/" + name).c_str(), [make](benchmark::State& state) {
    Ideal ideal = make();
    testing::SingularResult singular = testing::singular_std(ideal, kSingularTimeout);
    double ours = 0;
    std::size_t size = 0;
    for (auto _ : state) {
      GroebnerResult result = groebner_basis(ideal);
      if (!result.ok()) state.SkipWithError(result.message.c_str());
      ours = result.seconds;
      size = result.basis.size();
    }
    state.counters["basis"] = static_cast<double>(size);
    report_singular(state, singular, ours);
  })->Iterations(1)->Unit(benchmark::kMillisecond)->UseRealTime();
}

void register_all() {
  for (int n : {4, 5, 6, 7}) {
    register_groebner("katsura" + std::to_string(n) + "/degrevlex", [n] { return testing::katsura(n); });
  }
  for (int n : {5, 6}) {
    register_groebner("cyclic" + std::to_string(n) + "/degrevlex", [n] { return testing::cyclic(n); });
  }
  for (int n : {3, 4}) {
    register_groebner("katsura" + std::to_string(n) + "/lex",
                      [n] { return testing::katsura(n, MonomialOrder::lex()); });
  }
}

}  // namespace
}  // namespace sdfwb::algebra

int main(int argc, char** argv) {
  sdfwb::algebra::register_all();
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
