// The viewport's scene -> program compiles off the UI thread (issue 13,
// item 2): a request returns at once, its program is the direct compile, and
// newer requests supersede older ones still queued. No clock: the queue is
// paused (or its worker held) while requests arrive, so what runs is known.

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
    ProgramCompiler compiler(queue);
    EXPECT_FALSE(compiler.take());
    auto scene = defaultScene();
    compiler.request(scene, kOptions, 1);
    compiler.wait();
    EXPECT_FALSE(compiler.pending());
    std::optional<program::Program> program = compiler.take();
    ASSERT_TRUE(program);
    expectSameProgram(*program, program::compileScene(*scene, kOptions));
    EXPECT_FALSE(compiler.take());  // moved out
    EXPECT_EQ(compiler.error(), "");
    // the same key again is the same request: nothing compiles
    compiler.request(scene, kOptions, 1);
    EXPECT_FALSE(compiler.pending());
    EXPECT_EQ(compiler.compiles(), 1);
}

TEST(ProgramCompiler, RequestsWhileTheWorkerIsBusyCompileOnlyTheNewest) {
    jobs::JobQueue queue(1);
    ProgramCompiler compiler(queue);
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
    std::optional<program::Program> program = compiler.take();
    ASSERT_TRUE(program);
    expectSameProgram(*program, program::compileScene(*defaultScene(0.5 + 0.01 * 50), kOptions));
}

TEST(ProgramCompiler, APausedQueueRunsOneCompilePerCompilerWhateverWasAsked) {
    jobs::JobQueue queue(1);
    ProgramCompiler gl(queue), cpu(queue);  // two lanes on one worker, as the viewport has
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
    std::optional<program::Program> a = gl.take(), b = cpu.take();
    ASSERT_TRUE(a && b);
    expectSameProgram(*a, program::compileScene(*defaultScene(0.7), preview));
    expectSameProgram(*b, program::compileScene(*defaultScene(0.7), final));
}

TEST(ProgramCompiler, CancelDropsAQueuedCompile) {
    jobs::JobQueue queue(1);
    ProgramCompiler compiler(queue);
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
    ProgramCompiler compiler(queue);
    compiler.request(std::make_shared<const scene::Scene>(broken), kOptions, 1);
    compiler.wait();
    EXPECT_FALSE(compiler.take());
    EXPECT_NE(compiler.error(), "");
}

TEST(ProgramCompiler, DestroyedWithACompileQueuedOrRunning) {
    jobs::JobQueue queue(1);
    {
        ProgramCompiler compiler(queue);
        compiler.request(defaultScene(), kOptions, 1);
        compiler.request(defaultScene(0.6), kOptions, 2);
    }  // the job writes into its own result, which outlives the compiler
    drain(queue);
}

}  // namespace
}  // namespace sdfwb::ui
