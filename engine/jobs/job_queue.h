#pragma once
// One queue for background work (CPU renders, GL program builds,
// implicitization, equation checks, snapshot export): jobs run in order on
// the queue's worker threads; the submitter keeps a handle to cancel the job
// and read its progress, and polls it (finished()) instead of waiting, so an
// interactive thread never blocks. A job publishes its result through what
// its function captured; finished() orders that write before the read.
//
// Parallelism inside a job is the job's business (the CPU renderer spreads
// tiles over oneTBB); a queue's workers are for running jobs side by side.
// A worker can be bound to a resource for its whole life, such as a GL
// context current on its thread (WorkerScope). Workers run at background
// priority (thread_priority.h), below the thread that made the queue.

#include <atomic>
#include <condition_variable>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace sdfwb::jobs {

// The state one job shares between its worker and its submitter.
class Job {
public:
    // Asks the job to stop; a job still queued is dropped without running.
    void cancel() { cancel_ = true; }
    bool cancelled() const { return cancel_.load(); }
    // For code that takes a cancel flag (render::RenderControl, algebra budgets).
    const std::atomic<bool>& cancelFlag() const { return cancel_; }

    // Worker side: the fraction done, 0 to 1.
    void setProgress(double fraction) { progress_ = fraction; }
    double progress() const { return progress_.load(); }

    bool started() const { return started_.load(); }
    // The job's function returned, or the job was dropped before it ran.
    // Everything the function wrote before returning is visible after this
    // returns true.
    bool finished() const { return finished_.load(std::memory_order_acquire); }
    // Blocks until finished() (tests and command-line tools; interactive
    // callers poll finished() instead).
    void wait() const;
    // What the job's function threw (its what()), or ""; read after finished().
    const std::string& error() const { return error_; }

private:
    friend class JobQueue;
    void finish();

    mutable std::mutex mutex_;  // with finishedCondition_, for wait()
    mutable std::condition_variable finishedCondition_;
    std::atomic<bool> cancel_{false};
    std::atomic<bool> started_{false};
    std::atomic<bool> finished_{false};
    std::atomic<double> progress_{0.0};
    std::string error_;
};

using JobHandle = std::shared_ptr<Job>;

class JobQueue {
public:
    using Work = std::function<void(Job&)>;
    // Wraps a worker's whole life: it must call `runJobs` once and may hold
    // a resource around the call (make a GL context current, make a
    // renderer for it). Runs on the worker thread.
    using WorkerScope = std::function<void(const std::function<void()>& runJobs)>;

    explicit JobQueue(int workers = 1, WorkerScope scope = {});
    // Cancels every job and waits for the running ones to return.
    ~JobQueue();
    JobQueue(const JobQueue&) = delete;
    JobQueue& operator=(const JobQueue&) = delete;

    // Queues `work`; it runs once a worker is free (and the queue not paused).
    JobHandle submit(Work work);
    // Cancels every queued and running job.
    void cancelAll();
    // While paused, queued jobs wait; running ones go on.
    void setPaused(bool paused);
    // A job is queued or running.
    bool busy() const;

private:
    void run();
    struct Entry {
        Work work;
        JobHandle job;
    };

    mutable std::mutex mutex_;
    std::condition_variable wake_;
    std::deque<Entry> queue_;
    std::vector<JobHandle> running_;
    bool paused_ = false;
    bool stop_ = false;
    WorkerScope scope_;
    std::vector<std::thread> workers_;
};

}  // namespace sdfwb::jobs
