#include "app/gui/cpu_jobs.h"

#include <chrono>
#include <utility>

namespace sdfwb::app::gui {

CpuJobQueue::CpuJobQueue(int threads) : threads_(threads), worker_([this] { run(); }) {}

CpuJobQueue::~CpuJobQueue() {
    {
        std::lock_guard lock(mutex_);
        stop_ = true;
        queue_.clear();
    }
    cancel_ = true;
    wake_.notify_all();
    worker_.join();
}

void CpuJobQueue::submit(CpuJob job, bool replace) {
    {
        std::lock_guard lock(mutex_);
        if (replace) {
            queue_.clear();
            if (running_) cancel_ = true;
        }
        queue_.push_back(std::move(job));
    }
    wake_.notify_all();
}

void CpuJobQueue::cancelAll() {
    std::lock_guard lock(mutex_);
    queue_.clear();
    if (running_) cancel_ = true;
}

void CpuJobQueue::setPaused(bool paused) {
    {
        std::lock_guard lock(mutex_);
        paused_ = paused;
    }
    wake_.notify_all();
}

std::vector<CpuResult> CpuJobQueue::takeResults() {
    std::lock_guard lock(mutex_);
    return std::exchange(results_, {});
}

bool CpuJobQueue::busy() const {
    std::lock_guard lock(mutex_);
    return running_ || !queue_.empty();
}

void CpuJobQueue::run() {
    for (;;) {
        CpuJob job;
        {
            std::unique_lock lock(mutex_);
            wake_.wait(lock, [&] { return stop_ || (!paused_ && !queue_.empty()); });
            if (stop_) return;
            job = std::move(queue_.front());
            queue_.pop_front();
            running_ = true;
            cancel_ = false;
            progress_ = 0.0;
        }
        auto start = std::chrono::steady_clock::now();
        cpu::RenderControl control;
        control.threads = threads_;
        control.cancel = &cancel_;
        control.progress = [this](int done, int total) { progress_ = static_cast<double>(done) / total; };
        cpu::RenderOutcome outcome = cpu::renderCpu(job.program, control);
        double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::lock_guard lock(mutex_);
        running_ = false;
        progress_ = 0.0;
        if (!outcome.cancelled) results_.push_back({job.tag, std::move(outcome.frame), seconds});
    }
}

}  // namespace sdfwb::app::gui
