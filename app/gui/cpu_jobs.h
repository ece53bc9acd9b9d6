#pragma once
// CPU-backend renders on a worker thread for the GUI (the viewport's CPU
// backend, the compare view, thumbnails). Results come back through a queue
// the UI thread polls; a newer job can cancel the running one.

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <mutex>
#include <thread>
#include <vector>

#include "cpu/cpu_renderer.h"

namespace sdfwb::app::gui {

struct CpuJob {
    std::uint64_t tag = 0;       // the caller's name for the job
    program::Program program;
};

struct CpuResult {
    std::uint64_t tag = 0;
    image::Frame frame;
    double seconds = 0;
};

class CpuJobQueue {
public:
    // `threads` as in cpu::RenderControl (0: all hardware threads).
    explicit CpuJobQueue(int threads);
    ~CpuJobQueue();
    CpuJobQueue(const CpuJobQueue&) = delete;
    CpuJobQueue& operator=(const CpuJobQueue&) = delete;

    // Queues `job`; with `replace`, drops queued jobs and cancels the running one first.
    void submit(CpuJob job, bool replace);
    // Drops queued jobs and cancels the running one.
    void cancelAll();
    // While paused, queued jobs wait (the running one finishes).
    void setPaused(bool paused);
    std::vector<CpuResult> takeResults();
    // A job is queued or running.
    bool busy() const;
    // Tiles done / total of the running job (0 when none).
    double progress() const { return progress_.load(); }

private:
    void run();

    int threads_;
    mutable std::mutex mutex_;
    std::condition_variable wake_;
    std::deque<CpuJob> queue_;
    std::vector<CpuResult> results_;
    bool running_ = false;
    bool paused_ = false;
    bool stop_ = false;
    std::atomic<bool> cancel_{false};
    std::atomic<double> progress_{0.0};
    std::thread worker_;
};

}  // namespace sdfwb::app::gui
