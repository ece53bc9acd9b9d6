// The job queue: order, cancel of queued and running jobs, pause, errors and
// workers bound to a resource. Every wait is on an event the test triggers,
// never on a clock.

#include <gtest/gtest.h>

#include <future>
#include <stdexcept>
#include <thread>
#include <vector>

#include "jobs/job_queue.h"

namespace sdfwb {
namespace {

TEST(JobQueue, RunsJobsInOrderAndPublishesTheirResults) {
    jobs::JobQueue queue(1);
    std::vector<int> order;  // written by the worker, read after finished()
    std::vector<jobs::JobHandle> handles;
    for (int i = 0; i < 5; ++i) handles.push_back(queue.submit([&order, i](jobs::Job&) { order.push_back(i); }));
    handles.back()->wait();
    for (const jobs::JobHandle& h : handles) EXPECT_TRUE(h->finished());
    EXPECT_EQ(order, (std::vector<int>{0, 1, 2, 3, 4}));
    EXPECT_FALSE(queue.busy());
}

TEST(JobQueue, ACancelledQueuedJobNeverRuns) {
    jobs::JobQueue queue(1);
    std::promise<void> release;
    std::shared_future<void> gate = release.get_future().share();
    jobs::JobHandle first = queue.submit([gate](jobs::Job&) { gate.wait(); });
    bool ran = false;
    jobs::JobHandle second = queue.submit([&ran](jobs::Job&) { ran = true; });
    second->cancel();
    release.set_value();
    first->wait();
    second->wait();
    EXPECT_FALSE(ran);
    EXPECT_TRUE(second->cancelled());
    EXPECT_FALSE(first->cancelled());
}

TEST(JobQueue, CancelAllDropsQueuedJobsAndFlagsTheRunningOne) {
    jobs::JobQueue queue(1);
    std::promise<void> started;
    jobs::JobHandle running = queue.submit([&started](jobs::Job& job) {
        started.set_value();
        while (!job.cancelled()) std::this_thread::yield();
        job.setProgress(0.5);
    });
    bool ran = false;
    jobs::JobHandle queued = queue.submit([&ran](jobs::Job&) { ran = true; });
    started.get_future().wait();
    EXPECT_TRUE(queue.busy());
    queue.cancelAll();
    running->wait();
    queued->wait();
    EXPECT_FALSE(ran);
    EXPECT_TRUE(running->started());
    EXPECT_FALSE(queued->started());
    EXPECT_DOUBLE_EQ(running->progress(), 0.5);
}

TEST(JobQueue, PausedJobsWaitUntilResumed) {
    jobs::JobQueue queue(1);
    queue.setPaused(true);
    jobs::JobHandle job = queue.submit([](jobs::Job& j) { j.setProgress(1.0); });
    EXPECT_FALSE(job->started());  // no worker takes a job while paused
    EXPECT_TRUE(queue.busy());
    queue.setPaused(false);
    job->wait();
    EXPECT_DOUBLE_EQ(job->progress(), 1.0);
}

TEST(JobQueue, AThrowingJobReportsItsError) {
    jobs::JobQueue queue(1);
    jobs::JobHandle job = queue.submit([](jobs::Job&) { throw std::runtime_error("no luck"); });
    job->wait();
    EXPECT_EQ(job->error(), "no luck");
    // the worker goes on with the next job
    jobs::JobHandle next = queue.submit([](jobs::Job&) {});
    next->wait();
    EXPECT_EQ(next->error(), "");
}

thread_local int boundResource = 0;

TEST(JobQueue, WorkersRunInsideTheirScope) {
    jobs::JobQueue queue(2, [](const std::function<void()>& runJobs) {
        boundResource = 42;  // as a GL context made current for the worker's life
        runJobs();
        boundResource = 0;
    });
    std::vector<int> seen(4, 0);
    std::vector<jobs::JobHandle> handles;
    for (int i = 0; i < 4; ++i) {
        handles.push_back(queue.submit([&seen, i](jobs::Job&) { seen[static_cast<size_t>(i)] = boundResource; }));
    }
    for (const jobs::JobHandle& h : handles) h->wait();
    EXPECT_EQ(seen, (std::vector<int>{42, 42, 42, 42}));
}

TEST(JobQueue, DestroyingTheQueueCancelsAndWaits) {
    jobs::JobHandle running, queued;
    {
        jobs::JobQueue queue(1);
        std::promise<void> started;
        running = queue.submit([&started](jobs::Job& job) {
            started.set_value();
            while (!job.cancelled()) std::this_thread::yield();
        });
        queued = queue.submit([](jobs::Job&) {});
        started.get_future().wait();
    }
    EXPECT_TRUE(running->finished());
    EXPECT_TRUE(queued->finished());
    EXPECT_FALSE(queued->started());
}

}  // namespace
}  // namespace sdfwb
