#pragma once
// Limits for long computations: a time limit, a memory limit, a cancel flag
// and a progress callback. The Groebner engine checks them at safe points
// (between reduction steps and pair selections), so a computation that runs
// out of budget stops promptly with a "gave up after ..." message instead of
// hanging or exhausting memory.
//
// Memory is counted, not capped: GMP's allocator must not throw (GMP manual),
// so budgetGmpBytes() counts the bytes live in GMP integers through
// mp_set_memory_functions, and the engine adds an estimate of its own
// monomial storage. The count is process-wide: GMP numbers owned by other
// threads count against every budget running at the same time.

#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace sdfwb::algebra {

/// A flag another thread sets to stop a computation; share it by pointer.
class CancelToken {
 public:
  void cancel() { cancelled_.store(true, std::memory_order_relaxed); }
  bool cancelled() const { return cancelled_.load(std::memory_order_relaxed); }

 private:
  std::atomic<bool> cancelled_{false};
};

/// A snapshot reported to the progress callback.
struct Progress {
  double elapsedSeconds = 0;
  std::size_t basisSize = 0;   // current (not yet reduced) basis elements
  std::size_t pairsLeft = 0;   // critical pairs still to treat
  std::size_t memoryBytes = 0; // counted memory (see the file comment)
  const char* stage = "";       // "buchberger", "replay", "verification", "fglm", ... (static text)
  std::size_t primes = 0;       // modular method: primes finished so far (the counts above are per prime)
};

struct Budget {
  std::optional<double> timeLimitSeconds;
  std::optional<std::size_t> memoryLimitBytes;
  std::shared_ptr<const CancelToken> cancel;
  /// Called from the computing thread, at most every progressIntervalSeconds.
  std::function<void(const Progress&)> onProgress;
  double progressIntervalSeconds = 0.25;
};

/// How a budgeted computation ended.
enum class Status { Completed, Cancelled, TimeLimit, MemoryLimit };

/// "completed", "cancelled", "time limit", "memory limit".
const char* toString(Status status);

/// Thrown inside the engine at a safe point when the budget is exhausted;
/// public entry points catch it and report a Status instead.
struct BudgetExceeded {
  Status status;
  std::string message;  // "gave up after 2.0 s: time limit of 2 s reached (basis 31, 118 pairs left)"
};

/// Thrown by BudgetMonitor::addWork when a work limit set by the caller is
/// reached: not a budget of the user's, but a computation the caller tries
/// first and abandons when it costs more than an alternative (implicitize).
struct WorkLimitReached {};

/// Bytes currently held by GMP numbers in this process (counted once the
/// accounting allocator is installed; installGmpMemoryAccounting() is
/// called by every BudgetMonitor and is idempotent).
std::int64_t budgetGmpBytes();
void installGmpMemoryAccounting();

/// Tracks one computation against a Budget. Cheap to poll: tick() only looks
/// at the clock every few calls.
class BudgetMonitor {
 public:
  explicit BudgetMonitor(const Budget& budget);

  /// Throws BudgetExceeded when cancelled or over a limit; reports progress
  /// when due. `ownBytes` is the caller's estimate of its non-GMP memory.
  void check(const Progress& state, std::size_t ownBytes = 0);
  /// Like check, but reads the clock only every 64th call; for inner loops.
  void tick(const Progress& state, std::size_t ownBytes = 0) {
    if ((++ticks_ & 63u) == 0) check(state, ownBytes);
  }
  double elapsedSeconds() const;
  /// Primes finished by the modular method, reported with the progress.
  void setPrimes(std::size_t primes) { primes_ = primes; }

  /// Work counted in the engine's term operations (a term added to a
  /// reduction), a measure of cost independent of the clock and the load.
  /// Throws WorkLimitReached once the limit (if any) is passed.
  void addWork(std::uint64_t terms) {
    work_ += terms;
    if (workLimit_ && work_ > *workLimit_) throw WorkLimitReached{};
  }
  std::uint64_t work() const { return work_; }
  /// Counts from 0 against `limit` from now on; nullopt: no limit.
  void limitWork(std::optional<std::uint64_t> limit) {
    work_ = 0;
    workLimit_ = limit;
  }

 private:
  const Budget& budget_;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point nextReport_;
  std::int64_t gmpBytesAtStart_;
  std::uint32_t ticks_ = 0;
  std::size_t primes_ = 0;
  std::uint64_t work_ = 0;
  std::optional<std::uint64_t> workLimit_;
};

/// Runs `body`, which may throw BudgetExceeded, and records how it ended in
/// `result` (status and message) with the monitor's time (seconds): how the
/// public entry points turn the engine's exception into a Status.
template <class Result, class Body>
void runWithinBudget(Result& result, const BudgetMonitor& monitor, Body&& body) {
  try {
    body();
  } catch (const BudgetExceeded& e) {
    result.status = e.status;
    result.message = e.message;
  }
  result.seconds = monitor.elapsedSeconds();
}

}  // namespace sdfwb::algebra
