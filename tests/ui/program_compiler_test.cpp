// The viewport's scene -> program compiles off the UI thread (issue 13,
// item 2): a request returns at once, its program is the direct compile,
// newer requests drop older ones still queued, and one superseded after it
// started is handed out until the newest is ready. No clock: the queue is
// paused, or its worker held (by a job, or inside a compile), while requests
// arrive, so what runs is known.

#include <atomic>
#include <cstdint>
#include <future>
#include <memory>

#include <gtest/gtest.h>

#include "scene/scene_json.h"
#include "support/source_tree.h"
#include "ui/program_compiler.h"

namespace sdfwb::ui {
namespace {

std::shared_ptr<const scene::Scene> defaultScene(double ballRadius = 0.8) {
    scene::Scene scene = scene::loadSceneFile(sdfwb::test::sourceDir() + "/scenes/default.json");
    scene.root.children[0].children[0].set("radius", ballRadius);
    return std::make_shared<const scene::Scene>(std::move(scene));
}

const program::CompileOptions kOptions{320, 180, 1};

using Compiler = ProgramCompiler<std::uint64_t>;

// Two programs are the same compile: the same structure, numbers and size.
void expectSameProgram(const program::Program& a, const program::Program& b) {
    EXPECT_EQ(a.structureKey(), b.structureKey());
    EXPECT_EQ(a.params, b.params);
    EXPECT_EQ(a.code.size(), b.code.size());
    EXPECT_EQ(a.width, b.width);
    EXPECT_EQ(a.height, b.height);
    EXPECT_EQ(a.aa, b.aa);
    EXPECT_EQ(a.rootMin, b.rootMin);
    EXPECT_EQ(a.rootMax, b.rootMax);
}

// Waits for everything queued on `queue` before now (one worker: in order).
void drain(jobs::JobQueue& queue) {
    queue.submit([](jobs::Job&) {})->wait();
}

TEST(ProgramCompiler, TheProgramIsTheDirectCompileTakenOnce) {
    jobs::JobQueue queue(1);
    Compiler compiler(queue);
    EXPECT_FALSE(compiler.take());
    auto scene = defaultScene();
    compiler.request(scene, kOptions, 1);
    compiler.wait();
    EXPECT_FALSE(compiler.pending());
    std::optional<Compiler::Compiled> compiled = compiler.take();
    ASSERT_TRUE(compiled);
    EXPECT_EQ(compiled->tag, 1u);
    expectSameProgram(compiled->program, program::compileScene(*scene, kOptions));
    EXPECT_FALSE(compiler.take());  // moved out
    EXPECT_EQ(compiler.error(), "");
}

// The same tag while its program is on the way or untaken is the same
// request; asked again after it was taken, the caller dropped it, and it
// compiles again. (The viewport replans its lanes when a drag starts or ends
// on an unchanged scene and asks for the program it had taken: it waited,
// "compiling the scene", until the next edit.)
TEST(ProgramCompiler, TheSameTagCompilesOnceUntilTakenAndAgainAfter) {
    jobs::JobQueue queue(1);
    Compiler compiler(queue);
    auto scene = defaultScene();
    compiler.request(scene, kOptions, 1);
    compiler.request(scene, kOptions, 1);
    compiler.wait();
    compiler.request(scene, kOptions, 1);  // finished, not taken: still the same request
    EXPECT_FALSE(compiler.pending());
    EXPECT_EQ(compiler.compiles(), 1);
    ASSERT_TRUE(compiler.take());
    compiler.request(scene, kOptions, 1);
    compiler.wait();
    EXPECT_EQ(compiler.compiles(), 2);
    std::optional<Compiler::Compiled> again = compiler.take();
    ASSERT_TRUE(again);
    EXPECT_EQ(again->tag, 1u);
    expectSameProgram(again->program, program::compileScene(*scene, kOptions));
}

TEST(ProgramCompiler, RequestsWhileTheWorkerIsBusyCompileOnlyTheNewest) {
    jobs::JobQueue queue(1);
    Compiler compiler(queue);
    // hold the worker, as a long compile would, while 50 edits arrive
    std::promise<void> release;
    std::shared_future<void> released = release.get_future().share();
    jobs::JobHandle holder = queue.submit([released](jobs::Job&) { released.wait(); });
    for (int i = 1; i <= 50; ++i) {
        compiler.request(defaultScene(0.5 + 0.01 * i), kOptions, static_cast<std::uint64_t>(i));
        EXPECT_TRUE(compiler.pending());
        EXPECT_FALSE(compiler.take());  // never waits: nothing yet
    }
    release.set_value();
    compiler.wait();
    EXPECT_EQ(compiler.compiles(), 1);  // the 49 superseded ones were dropped unrun
    std::optional<Compiler::Compiled> compiled = compiler.take();
    ASSERT_TRUE(compiled);
    EXPECT_EQ(compiled->tag, 50u);
    expectSameProgram(compiled->program, program::compileScene(*defaultScene(0.5 + 0.01 * 50), kOptions));
}

TEST(ProgramCompiler, APausedQueueRunsOneCompilePerCompilerWhateverWasAsked) {
    jobs::JobQueue queue(1);
    Compiler gl(queue), cpu(queue);  // two lanes on one worker, as the viewport has
    queue.setPaused(true);
    const program::CompileOptions preview{80, 45, 1}, final{320, 180, 2};
    for (int i = 1; i <= 20; ++i) {
        gl.request(defaultScene(0.5 + 0.01 * i), preview, static_cast<std::uint64_t>(i));
        cpu.request(defaultScene(0.5 + 0.01 * i), final, static_cast<std::uint64_t>(i));
    }
    queue.setPaused(false);
    gl.wait();
    cpu.wait();
    EXPECT_EQ(gl.compiles(), 1);
    EXPECT_EQ(cpu.compiles(), 1);
    std::optional<Compiler::Compiled> a = gl.take(), b = cpu.take();
    ASSERT_TRUE(a && b);
    expectSameProgram(a->program, program::compileScene(*defaultScene(0.7), preview));
    expectSameProgram(b->program, program::compileScene(*defaultScene(0.7), final));
}

TEST(ProgramCompiler, AFinishedCompileNotYetTakenIsHandedOutAfterANewerRequest) {
    // a drag: each frame asks for a new state before taking the last one's
    jobs::JobQueue queue(1);
    Compiler compiler(queue);
    compiler.request(defaultScene(0.6), kOptions, 1);
    compiler.wait();
    queue.setPaused(true);  // the newer compile cannot run yet
    compiler.request(defaultScene(0.7), kOptions, 2);
    std::optional<Compiler::Compiled> older = compiler.take();
    ASSERT_TRUE(older);
    EXPECT_EQ(older->tag, 1u);
    expectSameProgram(older->program, program::compileScene(*defaultScene(0.6), kOptions));
    EXPECT_FALSE(compiler.take());  // taken once
    queue.setPaused(false);
    compiler.wait();
    std::optional<Compiler::Compiled> newest = compiler.take();
    ASSERT_TRUE(newest);
    EXPECT_EQ(newest->tag, 2u);
}

TEST(ProgramCompiler, ACompileSupersededWhileRunningIsTheFreshestUntilTheNewestIsReady) {
    // compiles that wait inside until let go, as long ones would
    std::promise<void> started[2], release[2];
    std::shared_future<void> released[2] = {release[0].get_future().share(), release[1].get_future().share()};
    auto count = std::make_shared<std::atomic<int>>(0);
    auto compile = [&, count](const scene::Scene& scene, const program::CompileOptions& options) {
        int n = (*count)++;
        if (n < 2) {
            started[n].set_value();
            released[n].wait();
        }
        return program::compileScene(scene, options);
    };
    jobs::JobQueue queue(1);
    Compiler compiler(queue, compile);
    compiler.request(defaultScene(0.6), kOptions, 1);
    started[0].get_future().wait();                    // 1 runs
    compiler.request(defaultScene(0.7), kOptions, 2);  // queued behind it
    compiler.request(defaultScene(0.8), kOptions, 3);  // drops 2, which never ran
    EXPECT_FALSE(compiler.take());                     // 1 is still running
    release[0].set_value();
    started[1].get_future().wait();  // 1 finished, 3 runs
    std::optional<Compiler::Compiled> freshest = compiler.take();
    ASSERT_TRUE(freshest);
    EXPECT_EQ(freshest->tag, 1u);
    expectSameProgram(freshest->program, program::compileScene(*defaultScene(0.6), kOptions));
    EXPECT_FALSE(compiler.take());
    release[1].set_value();
    compiler.wait();
    std::optional<Compiler::Compiled> newest = compiler.take();
    ASSERT_TRUE(newest);
    EXPECT_EQ(newest->tag, 3u);
    expectSameProgram(newest->program, program::compileScene(*defaultScene(0.8), kOptions));
    EXPECT_EQ(compiler.compiles(), 2);  // 1 and 3
}

TEST(ProgramCompiler, CancelDropsAQueuedCompile) {
    jobs::JobQueue queue(1);
    Compiler compiler(queue);
    queue.setPaused(true);
    compiler.request(defaultScene(), kOptions, 1);
    compiler.cancel();
    EXPECT_FALSE(compiler.pending());
    queue.setPaused(false);
    drain(queue);
    EXPECT_EQ(compiler.compiles(), 0);
    EXPECT_FALSE(compiler.take());
    // the key is forgotten: asking again compiles
    compiler.request(defaultScene(), kOptions, 1);
    compiler.wait();
    EXPECT_EQ(compiler.compiles(), 1);
    EXPECT_TRUE(compiler.take());
}

TEST(ProgramCompiler, AFailedCompileSaysWhyAndGivesNoProgram) {
    scene::Scene broken = *defaultScene();
    scene::Node formula = scene::Node::make(scene::NodeKind::Sdf);
    formula.set("formula", std::string("length(p) -"));  // not a formula: compileScene throws
    broken.root.children.push_back(formula);
    jobs::JobQueue queue(1);
    Compiler compiler(queue);
    compiler.request(std::make_shared<const scene::Scene>(broken), kOptions, 1);
    compiler.wait();
    EXPECT_FALSE(compiler.take());
    EXPECT_NE(compiler.error(), "");
}

TEST(ProgramCompiler, DestroyedWithACompileQueuedOrRunning) {
    jobs::JobQueue queue(1);
    {
        Compiler compiler(queue);
        compiler.request(defaultScene(), kOptions, 1);
        compiler.request(defaultScene(0.6), kOptions, 2);
    }  // the job writes into its own result, which outlives the compiler
    drain(queue);
}

}  // namespace
}  // namespace sdfwb::ui
