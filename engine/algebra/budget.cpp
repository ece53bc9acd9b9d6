#include "algebra/budget.h"

#include <gmp.h>

#include <cstdio>
#include <cstdlib>
#include <mutex>

namespace sdfwb::algebra {

namespace {

std::atomic<std::int64_t> gGmpBytes{0};

// Plain malloc/realloc/free plus a byte count. Blocks allocated before the
// install are freed here too (GMP passes their sizes), which only makes the
// count drift low; budgets compare differences, so that is harmless. On
// allocation failure we must neither throw nor return null (GMP would abort
// with a less clear message), so we print one line and abort.
[[noreturn]] void outOfMemory(std::size_t size) {
  std::fprintf(stderr, "sdfwb algebra: out of memory allocating %zu bytes for GMP\n", size);
  std::abort();
}

void* countingAlloc(std::size_t size) {
  void* p = std::malloc(size);
  if (!p) outOfMemory(size);
  gGmpBytes.fetch_add(static_cast<std::int64_t>(size), std::memory_order_relaxed);
  return p;
}

void* countingRealloc(void* old, std::size_t oldSize, std::size_t newSize) {
  void* p = std::realloc(old, newSize);
  if (!p) outOfMemory(newSize);
  gGmpBytes.fetch_add(static_cast<std::int64_t>(newSize) - static_cast<std::int64_t>(oldSize),
                        std::memory_order_relaxed);
  return p;
}

void countingFree(void* p, std::size_t size) {
  std::free(p);
  gGmpBytes.fetch_sub(static_cast<std::int64_t>(size), std::memory_order_relaxed);
}

std::string formatSeconds(double s) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.1f s", s);
  return buffer;
}

std::string formatBytes(std::size_t bytes) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.0f MB", static_cast<double>(bytes) / (1024.0 * 1024.0));
  return buffer;
}

}  // namespace

const char* toString(Status status) {
  switch (status) {
    case Status::Completed: return "completed";
    case Status::Cancelled: return "cancelled";
    case Status::TimeLimit: return "time limit";
    case Status::MemoryLimit: return "memory limit";
  }
  return "?";
}

std::int64_t budgetGmpBytes() { return gGmpBytes.load(std::memory_order_relaxed); }

void installGmpMemoryAccounting() {
  static std::once_flag once;
  std::call_once(once, [] { mp_set_memory_functions(countingAlloc, countingRealloc, countingFree); });
}

BudgetMonitor::BudgetMonitor(const Budget& budget) : budget_(budget) {
  installGmpMemoryAccounting();
  start_ = std::chrono::steady_clock::now();
  nextReport_ = start_;
  gmpBytesAtStart_ = budgetGmpBytes();
}

double BudgetMonitor::elapsedSeconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void BudgetMonitor::check(const Progress& state, std::size_t ownBytes) {
  auto now = std::chrono::steady_clock::now();
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  std::int64_t gmp = budgetGmpBytes() - gmpBytesAtStart_;
  const std::size_t memory = ownBytes + static_cast<std::size_t>(gmp > 0 ? gmp : 0);

  auto giveUp = [&](Status status, const std::string& reason) {
    // Where it was: the stage, then what that stage counts.
    std::string where = *state.stage ? state.stage : "";
    auto add = [&where](const std::string& part) { where += (where.empty() ? "" : ", ") + part; };
    if (state.basisSize || state.pairsLeft) {
      add("basis " + std::to_string(state.basisSize) + ", " + std::to_string(state.pairsLeft) + " pairs left");
    }
    if (primes_) add(std::to_string(primes_) + (primes_ == 1 ? " prime" : " primes") + " done");
    if (!where.empty()) where = " (" + where + ")";
    // a cancel is the caller's doing, not the engine giving up
    std::string head = status == Status::Cancelled ? "cancelled after " + formatSeconds(elapsed)
                                                   : "gave up after " + formatSeconds(elapsed) + ": " + reason;
    throw BudgetExceeded{status, head + where};
  };
  if (budget_.cancel && budget_.cancel->cancelled()) giveUp(Status::Cancelled, {});
  if (budget_.timeLimitSeconds && elapsed > *budget_.timeLimitSeconds) {
    giveUp(Status::TimeLimit, "time limit of " + formatSeconds(*budget_.timeLimitSeconds) + " reached");
  }
  if (budget_.memoryLimitBytes && memory > *budget_.memoryLimitBytes) {
    giveUp(Status::MemoryLimit, "memory limit of " + formatBytes(*budget_.memoryLimitBytes) +
                                      " reached (" + formatBytes(memory) + " in use)");
  }
  if (budget_.onProgress && now >= nextReport_) {
    Progress report = state;
    report.elapsedSeconds = elapsed;
    report.memoryBytes = memory;
    report.primes = primes_;
    budget_.onProgress(report);
    nextReport_ = now + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                             std::chrono::duration<double>(budget_.progressIntervalSeconds));
  }
}

}  // namespace sdfwb::algebra
