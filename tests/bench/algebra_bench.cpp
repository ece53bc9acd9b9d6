// Our Groebner bases and implicitizations against Singular, measured in the
// same run on the same ideals.
//
// Each benchmark runs our computation once (Iterations(1): these are
// seconds-long exact computations, not microbenchmarks) and reports:
//   ours_s, ours_cpu_s          our wall-clock and CPU time
//   singular_s, singular_cpu_s  Singular's, for the command named in the
//                               benchmark (std, stdfglm or eliminate), timed
//                               inside Singular (its startup excluded)
//   cpu_ratio                   ours_cpu_s / singular_cpu_s
// A Singular time of -1 means it did not finish within its timeout. CPU time
// is the fairer comparison on a shared machine; wall time is what a user sees.
//
//   build/tests/bench/algebra_bench --benchmark_filter=implicitize/
//   build/tests/bench/algebra_bench --benchmark_filter=implicitize-lex/
//   SDFWB_SINGULAR_TIMEOUT=600 build/tests/bench/algebra_bench --benchmark_filter=lex
// SDFWB_SINGULAR_TIMEOUT (default 120 s) bounds each Singular run,
// SDFWB_OURS_TIMEOUT (default 600 s) each of ours.

#include "algebra/groebner.h"
#include "algebra/implicitization.h"
#include "example_systems.h"
#include "singular_runner.h"

#include <benchmark/benchmark.h>

#include <ctime>
#include <cstdlib>
#include <functional>

namespace sdfwb::algebra {
namespace {

double singularTimeout() {
  const char* value = std::getenv("SDFWB_SINGULAR_TIMEOUT");
  return value ? std::atof(value) : 120.0;
}

// Ours gets its own limit, so a short Singular timeout still lets ours finish.
double oursTimeout() {
  const char* value = std::getenv("SDFWB_OURS_TIMEOUT");
  return value ? std::atof(value) : 600.0;
}

double cpuNow() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

void report(benchmark::State& state, const testing::SingularResult& singular, double oursWall, double oursCpu) {
  state.counters["ours_s"] = oursWall;
  state.counters["ours_cpu_s"] = oursCpu;
  state.counters["singular_s"] = singular.ok ? singular.seconds : -1;
  state.counters["singular_cpu_s"] = singular.ok ? singular.cpuSeconds : -1;
  // Times under a millisecond count as a millisecond on both sides.
  if (singular.ok) state.counters["cpu_ratio"] = std::max(oursCpu, 0.001) / std::max(singular.cpuSeconds, 0.001);
}

void registerGroebner(const std::string& name, std::function<Ideal()> make, const std::string& singularCommand) {
  benchmark::RegisterBenchmark(("groebner/" + name).c_str(), [make, singularCommand](benchmark::State& state) {
    const Ideal ideal = make();
    const testing::SingularResult singular = testing::singularStd(ideal, singularTimeout(), singularCommand);
    double wall = 0, cpu = 0;
    for (auto _ : state) {
      const double start = cpuNow();
      GroebnerResult result = groebnerBasis(ideal);
      cpu = cpuNow() - start;
      wall = result.seconds;
      if (!result.ok()) state.SkipWithError(result.message.c_str());
      state.counters["basis"] = static_cast<double>(result.basis.size());
      state.counters["primes"] = static_cast<double>(result.stats.primes);
      if (singular.ok && result.basis != singular.basis) state.SkipWithError("bases differ from Singular's");
    }
    report(state, singular, wall, cpu);
  })->Iterations(1)->Unit(benchmark::kMillisecond)->UseRealTime();
}

void registerImplicitization(const testing::NamedParametrization& example, DenominatorStrategy denominator,
                              EliminationOrder order = EliminationOrder::BlockDegrevlex) {
  const std::string prefix = denominator == DenominatorStrategy::Product ? "implicitize-product/"
                             : order == EliminationOrder::Lex           ? "implicitize-lex/"
                                                                        : "implicitize/";
  benchmark::RegisterBenchmark((prefix + example.name).c_str(), [example, denominator, order](benchmark::State& state) {
    const EliminationProblem problem = implicitizationIdeal(example.parametrization, denominator);
    const RingPtr target = Ring::make(example.parametrization.coordinates);
    const testing::SingularResult singular =
        testing::singularEliminate(problem.ideal, problem.eliminated, target, singularTimeout());
    double wall = 0, cpu = 0;
    for (auto _ : state) {
      ImplicitizationOptions options;
      options.denominator = denominator;
      options.order = order;
      options.groebner.budget.timeLimitSeconds = oursTimeout();
      const double start = cpuNow();
      ImplicitizationResult result = implicitize(example.parametrization, options);
      cpu = cpuNow() - start;
      wall = result.seconds;
      if (!result.ok()) {
        state.SkipWithError(result.message.c_str());
        continue;
      }
      state.SetLabel(result.method);
      state.counters["primes"] = static_cast<double>(result.stats.primes);
      state.counters["generators"] = static_cast<double>(result.generators.size());
      if (!result.generators.empty()) {
        state.counters["degree"] = static_cast<double>(result.generators.front().totalDegree());
        state.counters["terms"] = static_cast<double>(result.generators.front().termCount());
      }
    }
    report(state, singular, wall, cpu);
  })->Iterations(1)->Unit(benchmark::kMillisecond)->UseRealTime();
}

void registerAll() {
  for (int n : {5, 6, 7, 8}) {
    registerGroebner("katsura" + std::to_string(n) + "/degrevlex", [n] { return testing::katsura(n); }, "std");
  }
  for (int n : {5, 6, 7}) {
    registerGroebner("cyclic" + std::to_string(n) + "/degrevlex", [n] { return testing::cyclic(n); }, "std");
  }
  // Lex: ours goes through degrevlex and FGLM; Singular is given both its
  // plain std in lex and its own stdfglm.
  for (int n : {4, 5, 6}) {
    for (const char* command : {"std", "stdfglm"}) {
      registerGroebner("katsura" + std::to_string(n) + "/lex/vs-" + command,
                        [n] { return testing::katsura(n, MonomialOrder::lex()); }, command);
    }
  }
  // Cyclic-4 is not zero-dimensional: no FGLM for it.
  registerGroebner("cyclic4/lex/vs-std", [] { return testing::cyclic(4, MonomialOrder::lex()); }, "std");
  for (const char* command : {"std", "stdfglm"}) {
    registerGroebner(std::string("cyclic5/lex/vs-") + command, [] { return testing::cyclic(5, MonomialOrder::lex()); },
                      command);
  }
  // A weighted order and an elimination (block) order.
  for (int n : {4, 5, 6}) {
    registerGroebner("katsura" + std::to_string(n) + "/weighted", [n] {
      std::vector<std::int64_t> weights;
      for (int i = 0; i <= n; ++i) weights.push_back(1 + i % 2);
      return testing::katsura(n, MonomialOrder::weighted(weights, MonomialOrder::degrevlex()));
    }, "std");
    registerGroebner("katsura" + std::to_string(n) + "/elimination-2", [n] {
      return testing::katsura(n, MonomialOrder::elimination(2));
    }, "std");
  }
  for (const testing::NamedParametrization& example : testing::classicParametrizations()) {
    registerImplicitization(example, DenominatorStrategy::Lcm);
  }
  for (const testing::NamedParametrization& example : testing::patchParametrizations()) {
    registerImplicitization(example, DenominatorStrategy::Lcm);
  }
  // The textbook's pure lex order against the default block order (Singular
  // runs its eliminate, a block order, in both).
  for (const testing::NamedParametrization& example : testing::classicParametrizations()) {
    registerImplicitization(example, DenominatorStrategy::Lcm, EliminationOrder::Lex);
  }
  for (const testing::NamedParametrization& example : testing::classicParametrizations()) {
    if (example.name.find("half-angle") != std::string::npos) {
      registerImplicitization(example, DenominatorStrategy::Product);
    }
  }
}

}  // namespace
}  // namespace sdfwb::algebra

int main(int argc, char** argv) {
  sdfwb::algebra::registerAll();
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
