#include "jobs/parallel_for.h"

#ifdef SDFWB_PLAIN_THREADS
#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>
#else
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <climits>

#include "jobs/thread_priority.h"
#endif

namespace sdfwb::jobs {

#ifdef SDFWB_PLAIN_THREADS

namespace {
thread_local int threadLimit = 0;  // set by withThreads
thread_local bool inLoop = false;  // the thread runs a parallelFor body

// Gives a thread_local a value for a scope, then its outer value back.
template <typename T>
class ScopedValue {
public:
    ScopedValue(T& variable, T value) : variable_(variable), outer_(variable) { variable_ = value; }
    ~ScopedValue() { variable_ = outer_; }
    ScopedValue(const ScopedValue&) = delete;
    ScopedValue& operator=(const ScopedValue&) = delete;

private:
    T& variable_;
    T outer_;
};
}  // namespace

int defaultThreads() { return std::max(1, static_cast<int>(std::thread::hardware_concurrency())); }

void parallelFor(int count, const std::function<void(int)>& body) {
    if (inLoop) {
        // The outer loop already runs on every thread the limit allows.
        for (int i = 0; i < count; ++i) body(i);
        return;
    }
    const int limit = threadLimit > 0 ? threadLimit : defaultThreads();
    const int threads = std::min(limit, count);
    std::atomic<int> next{0};
    std::mutex failureMutex;
    std::exception_ptr failure;  // the first exception a body threw, rethrown here as oneTBB does
    auto run = [&] {
        ScopedValue<bool> scope(inLoop, true);
        try {
            for (int i = next++; i < count; i = next++) body(i);
        } catch (...) {
            next = count;
            std::lock_guard lock(failureMutex);
            if (!failure) failure = std::current_exception();
        }
    };
    std::vector<std::thread> helpers;
    for (int t = 1; t < threads; ++t) helpers.emplace_back(run);
    if (threads > 0) run();
    for (std::thread& helper : helpers) helper.join();
    if (failure) std::rethrow_exception(failure);
}

void withThreads(int threads, const std::function<void()>& work) {
    ScopedValue<int> scope(threadLimit, threads > 0 ? threads : defaultThreads());
    work();
}

#else

int defaultThreads() { return tbb::this_task_arena::max_concurrency(); }

namespace {
// The nice value this pool thread last took from a caller (thread_priority.h).
thread_local int niceTaken = INT_MIN;
// parallelFor calls waiting on this thread: a thread that called one may run
// other callers' bodies while it waits, and must keep its own priority.
thread_local int callsWaiting = 0;
}  // namespace

void parallelFor(int count, const std::function<void(int)>& body) {
    // oneTBB's pool threads serve every caller; they run a body at least as
    // nice as its caller, so that a background render's tiles do not compete
    // with the window's thread. (Plain threads inherit their creator's.)
    const int callerNice = threadNice();
    ++callsWaiting;
    struct Leave {
        ~Leave() { --callsWaiting; }
    } leave;
    // One index per task: tiles and grid cells differ widely in cost.
    tbb::parallel_for(
        tbb::blocked_range<int>(0, count, 1),
        [&](const tbb::blocked_range<int>& range) {
            if (callsWaiting == 0 && niceTaken != callerNice) {
                becomeAtLeastAsNice(callerNice);
                niceTaken = callerNice;
            }
            for (int i = range.begin(); i != range.end(); ++i) body(i);
        },
        tbb::simple_partitioner());
}

void withThreads(int threads, const std::function<void()>& work) {
    tbb::task_arena arena(threads > 0 ? threads : defaultThreads());
    arena.execute(work);
}

#endif

}  // namespace sdfwb::jobs
