// Data-parallel loops (jobs/parallel_for.h): every index once, the thread
// limit of withThreads, nested limits, and a body's exception reaching the
// caller. The same tests run on oneTBB and, in the ThreadSanitizer build, on
// plain threads.

#include <gtest/gtest.h>

#include <atomic>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

#include "jobs/parallel_for.h"

namespace sdfwb {
namespace {

TEST(ParallelFor, RunsEveryIndexExactlyOnce) {
    std::vector<std::atomic<int>> runs(1000);
    jobs::parallelFor(static_cast<int>(runs.size()), [&](int i) { ++runs[static_cast<size_t>(i)]; });
    for (const std::atomic<int>& r : runs) EXPECT_EQ(r.load(), 1);
}

TEST(ParallelFor, AnEmptyRangeRunsNothing) {
    std::atomic<int> runs{0};
    jobs::parallelFor(0, [&](int) { ++runs; });
    EXPECT_EQ(runs.load(), 0);
}

TEST(ParallelFor, OneThreadRunsEverythingNestedOrNotOnTheCallingThread) {
    const std::thread::id caller = std::this_thread::get_id();
    std::atomic<int> elsewhere{0}, runs{0};
    jobs::withThreads(1, [&] {
        jobs::parallelFor(20, [&](int) {
            jobs::parallelFor(10, [&](int) {
                ++runs;
                if (std::this_thread::get_id() != caller) ++elsewhere;
            });
        });
    });
    EXPECT_EQ(runs.load(), 200);
    EXPECT_EQ(elsewhere.load(), 0);
}

TEST(ParallelFor, ALoopInsideALimitedLoopKeepsTheLimit) {
    std::mutex idsMutex;
    std::set<std::thread::id> ids;
    std::atomic<int> runs{0};
    jobs::withThreads(2, [&] {
        jobs::parallelFor(8, [&](int) {
            jobs::parallelFor(8, [&](int) {
                ++runs;
                std::lock_guard lock(idsMutex);
                ids.insert(std::this_thread::get_id());
            });
        });
    });
    EXPECT_EQ(runs.load(), 64);
    EXPECT_LE(ids.size(), 2u);
}

TEST(ParallelFor, ABodysExceptionReachesTheCaller) {
    std::atomic<int> runs{0};
    EXPECT_THROW(jobs::parallelFor(100,
                                   [&](int i) {
                                       ++runs;
                                       if (i == 37) throw std::runtime_error("index 37");
                                   }),
                 std::runtime_error);
    EXPECT_LE(runs.load(), 100);
}

TEST(ParallelFor, ZeroThreadsMeansTheMachinesCount) {
    EXPECT_GE(jobs::defaultThreads(), 1);
    std::atomic<int> runs{0};
    jobs::withThreads(0, [&] { jobs::parallelFor(10, [&](int) { ++runs; }); });
    EXPECT_EQ(runs.load(), 10);
}

}  // namespace
}  // namespace sdfwb
