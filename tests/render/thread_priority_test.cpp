// Background threads yield to the interactive one (jobs/thread_priority.h):
// job queue workers run nicer than the thread that made the queue, loops
// started by background work run their bodies at least as nice as it, and a
// thread never becomes less nice than it was.

#include <gtest/gtest.h>

#include <algorithm>
#include <condition_variable>
#include <mutex>
#include <thread>

#include "jobs/job_queue.h"
#include "jobs/parallel_for.h"
#include "jobs/thread_priority.h"

namespace sdfwb {
namespace {

int backgroundNiceOf(int nice) { return std::min(jobs::kNicest, nice + jobs::kBackgroundNiceIncrement); }

TEST(ThreadPriority, AThreadBecomesNicerButNeverLessNice) {
    std::thread([] {
        const int start = jobs::threadNice();
        jobs::becomeAtLeastAsNice(start + 3);
        EXPECT_EQ(jobs::threadNice(), std::min(jobs::kNicest, start + 3));
        jobs::becomeAtLeastAsNice(start);
        EXPECT_EQ(jobs::threadNice(), std::min(jobs::kNicest, start + 3));
        jobs::becomeAtLeastAsNice(1000);
        EXPECT_EQ(jobs::threadNice(), jobs::kNicest);
    }).join();
}

TEST(ThreadPriority, BecomingNicerLeavesOtherThreadsAlone) {
    const int mine = jobs::threadNice();
    std::thread([] { jobs::becomeBackgroundThread(); }).join();
    EXPECT_EQ(jobs::threadNice(), mine);
}

TEST(ThreadPriority, JobQueueWorkersRunAtBackgroundPriority) {
    const int mine = jobs::threadNice();
    int seenInScope = -100, seenInJob = -100;
    jobs::JobQueue queue(1, [&](const std::function<void()>& runJobs) {
        seenInScope = jobs::threadNice();  // a GL context made here starts its threads at this priority
        runJobs();
    });
    queue.submit([&](jobs::Job&) { seenInJob = jobs::threadNice(); })->wait();
    EXPECT_EQ(seenInScope, backgroundNiceOf(mine));
    EXPECT_EQ(seenInJob, backgroundNiceOf(mine));
    EXPECT_EQ(jobs::threadNice(), mine);
}

// Runs a loop whose bodies run on the calling thread and on at least one pool
// thread; returns the least nice value a body ran at.
int leastNiceOfALoopOnThePool() {
    std::mutex mutex;
    std::condition_variable ranElsewhere;
    int leastNice = 100, runsElsewhere = 0;
    const std::thread::id caller = std::this_thread::get_id();
    jobs::parallelFor(64, [&](int) {
        std::unique_lock lock(mutex);
        leastNice = std::min(leastNice, jobs::threadNice());
        if (std::this_thread::get_id() != caller) {
            ++runsElsewhere;
            ranElsewhere.notify_all();
        } else {
            ranElsewhere.wait(lock, [&] { return runsElsewhere > 0; });
        }
    });
    return leastNice;
}

TEST(ThreadPriority, ALoopOfABackgroundJobRunsEveryBodyAtLeastAsNice) {
    if (jobs::defaultThreads() < 2) GTEST_SKIP() << "needs a pool thread beside the caller";
    // the pool's threads first serve this less nice thread (in a process of
    // its own, as CTest runs each test, they are at its priority then)
    const int mine = jobs::threadNice();
    leastNiceOfALoopOnThePool();
    jobs::JobQueue queue(1);
    int jobNice = -100, leastNice = -100;
    queue
        .submit([&](jobs::Job&) {
            jobNice = jobs::threadNice();
            leastNice = leastNiceOfALoopOnThePool();
        })
        ->wait();
    EXPECT_EQ(jobNice, backgroundNiceOf(mine));
    EXPECT_GE(leastNice, jobNice);
}

}  // namespace
}  // namespace sdfwb
