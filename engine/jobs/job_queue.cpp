#include "jobs/job_queue.h"

#include <algorithm>
#include <exception>

#include "jobs/thread_priority.h"

namespace sdfwb::jobs {

void Job::wait() const {
    std::unique_lock lock(mutex_);
    finishedCondition_.wait(lock, [&] { return finished(); });
}

void Job::finish() {
    {
        std::lock_guard lock(mutex_);
        // the work's results are written before this store and read after an acquiring load
        finished_.store(true, std::memory_order_release);
    }
    finishedCondition_.notify_all();
}

JobQueue::JobQueue(int workers, WorkerScope scope) : scope_(std::move(scope)) {
    for (int i = 0; i < std::max(1, workers); ++i) {
        workers_.emplace_back([this] {
            // before the scope, so that threads started inside it inherit it
            becomeBackgroundThread();
            if (scope_) {
                scope_([this] { run(); });
            } else {
                run();
            }
        });
    }
}

JobQueue::~JobQueue() {
    {
        std::lock_guard lock(mutex_);
        stop_ = true;
    }
    cancelAll();
    wake_.notify_all();
    for (std::thread& worker : workers_) worker.join();
}

JobHandle JobQueue::submit(Work work) {
    auto job = std::make_shared<Job>();
    {
        std::lock_guard lock(mutex_);
        queue_.push_back({std::move(work), job});
    }
    wake_.notify_one();
    return job;
}

void JobQueue::cancelAll() {
    std::lock_guard lock(mutex_);
    for (Entry& entry : queue_) {
        entry.job->cancel();
        entry.job->finish();
    }
    queue_.clear();
    for (const JobHandle& job : running_) job->cancel();
}

void JobQueue::setPaused(bool paused) {
    {
        std::lock_guard lock(mutex_);
        paused_ = paused;
    }
    wake_.notify_all();
}

bool JobQueue::busy() const {
    std::lock_guard lock(mutex_);
    return !queue_.empty() || !running_.empty();
}

void JobQueue::run() {
    for (;;) {
        Entry entry;
        {
            std::unique_lock lock(mutex_);
            wake_.wait(lock, [&] { return stop_ || (!paused_ && !queue_.empty()); });
            if (stop_) return;
            entry = std::move(queue_.front());
            queue_.pop_front();
            running_.push_back(entry.job);
        }
        Job& job = *entry.job;
        job.started_ = true;
        try {
            if (!job.cancelled()) entry.work(job);
        } catch (const std::exception& error) {
            job.error_ = error.what();
        }
        std::lock_guard lock(mutex_);
        running_.erase(std::find(running_.begin(), running_.end(), entry.job));
        job.finish();
    }
}

}  // namespace sdfwb::jobs
