// Two contexts sharing objects, current on two threads: the pattern of the
// GLSL backend's compile worker.
#include <gtest/gtest.h>

#include <atomic>
#include <future>
#include <memory>
#include <thread>
#include <vector>

#include "gl_test_support.h"
#include "glcontext/fragment_evaluator.h"

using sdfwb::glcontext::EvaluatorInput;
using sdfwb::glcontext::FragmentEvaluator;
using sdfwb::glcontext::GlContext;
using sdfwb::glcontext::GlFunctions;
using sdfwb::glcontext::InputLayout;
using sdfwb::glcontext::ScopedCurrent;

namespace {

using SharedContextTest = sdfwb::test::GlTest;

constexpr const char* kSquares =
    "uniform samplerBuffer values;\n"
    "void main() { float v = texelFetch(values, evalIndex()).x; evalResult = vec4(v * v); }\n";

// Evaluates kSquares on 0..count-1 and says whether every square came out right.
bool squaresAreRight(const FragmentEvaluator& evaluator, const GlFunctions& gl, int count) {
  EvaluatorInput values{"values", 1, InputLayout::Buffer, {}};
  for (int i = 0; i < count; ++i) values.values.push_back(static_cast<float>(i));
  std::vector<float> out = evaluator.evaluate(gl, count, 1, std::vector{values});
  for (int i = 0; i < count; ++i) {
    if (out[static_cast<std::size_t>(i) * 4] != static_cast<float>(i * i)) return false;
  }
  return true;
}

struct Compiled {
  std::unique_ptr<FragmentEvaluator> evaluator;
  GLsync ready;
};

TEST_F(SharedContextTest, WorkerCompilesAndTheCallerRendersWithTheProgram) {
  std::unique_ptr<GlContext> workerContext = context().createShared();
  // createShared must not disturb the caller's current context.
  ASSERT_NE(gl().GetString(GL_RENDERER), nullptr);

  std::future<Compiled> compiled = std::async(std::launch::async, [&] {
    ScopedCurrent current(*workerContext);
    const GlFunctions& gl = workerContext->gl();
    Compiled result{std::make_unique<FragmentEvaluator>(gl, kSquares), nullptr};
    // The caller may use the program only once this fence has passed.
    result.ready = gl.FenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
    gl.Flush();
    return result;
  });
  Compiled result = compiled.get();
  GLenum waited = gl().ClientWaitSync(result.ready, GL_SYNC_FLUSH_COMMANDS_BIT, 10'000'000'000ull);
  EXPECT_TRUE(waited == GL_ALREADY_SIGNALED || waited == GL_CONDITION_SATISFIED) << waited;
  gl().DeleteSync(result.ready);
  workerContext.reset();  // the program lives on in the share group

  EXPECT_TRUE(squaresAreRight(*result.evaluator, gl(), 64));
}

TEST_F(SharedContextTest, BothThreadsRenderAtTheSameTime) {
  FragmentEvaluator evaluator(gl(), kSquares);
  gl().Finish();  // the program is complete before the worker uses it
  std::unique_ptr<GlContext> workerContext = context().createShared();

  constexpr int kRounds = 20;
  std::atomic<int> workerGood{0};
  std::thread worker([&] {
    ScopedCurrent current(*workerContext);
    for (int round = 0; round < kRounds; ++round) {
      if (squaresAreRight(evaluator, workerContext->gl(), 257)) ++workerGood;
    }
  });
  int callerGood = 0;
  for (int round = 0; round < kRounds; ++round) {
    if (squaresAreRight(evaluator, gl(), 301)) ++callerGood;
  }
  worker.join();
  EXPECT_EQ(callerGood, kRounds);
  EXPECT_EQ(workerGood.load(), kRounds);
}

}  // namespace
