#include "algebra/budget.h"

#include <gmp.h>

#include <cstdio>
#include <cstdlib>
#include <mutex>

namespace sdfwb::algebra {

namespace {

std::atomic<std::int64_t> g_gmp_bytes{0};

// Plain malloc/realloc/free plus a byte count. Blocks allocated before the
// install are freed here too (GMP passes their sizes), which only makes the
// count drift low; budgets compare differences, so that is harmless. On
// allocation failure we must neither throw nor return null (GMP would abort
// with a less clear message), so we print one line and abort.
[[noreturn]] void out_of_memory(std::size_t size) {
  std::fprintf(stderr, "sdfwb algebra: out of memory allocating %zu bytes for GMP\n", size);
  std::abort();
}

void* counting_alloc(std::size_t size) {
  void* p = std::malloc(size);
  if (!p) out_of_memory(size);
  g_gmp_bytes.fetch_add(static_cast<std::int64_t>(size), std::memory_order_relaxed);
  return p;
}

void* counting_realloc(void* old, std::size_t old_size, std::size_t new_size) {
  void* p = std::realloc(old, new_size);
  if (!p) out_of_memory(new_size);
  g_gmp_bytes.fetch_add(static_cast<std::int64_t>(new_size) - static_cast<std::int64_t>(old_size),
                        std::memory_order_relaxed);
  return p;
}

void counting_free(void* p, std::size_t size) {
  std::free(p);
  g_gmp_bytes.fetch_sub(static_cast<std::int64_t>(size), std::memory_order_relaxed);
}

std::string format_seconds(double s) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.1f s", s);
  return buffer;
}

std::string format_bytes(std::size_t bytes) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.0f MB", static_cast<double>(bytes) / (1024.0 * 1024.0));
  return buffer;
}

}  // namespace

const char* to_string(Status status) {
  switch (status) {
    case Status::completed: return "completed";
    case Status::cancelled: return "cancelled";
    case Status::time_limit: return "time limit";
    case Status::memory_limit: return "memory limit";
  }
  return "?";
}

std::int64_t budget_gmp_bytes() { return g_gmp_bytes.load(std::memory_order_relaxed); }

void install_gmp_memory_accounting() {
  static std::once_flag once;
  std::call_once(once, [] { mp_set_memory_functions(counting_alloc, counting_realloc, counting_free); });
}

BudgetMonitor::BudgetMonitor(const Budget& budget) : budget_(budget) {
  install_gmp_memory_accounting();
  start_ = std::chrono::steady_clock::now();
  next_report_ = start_;
  gmp_bytes_at_start_ = budget_gmp_bytes();
}

double BudgetMonitor::elapsed_seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void BudgetMonitor::check(const Progress& state, std::size_t own_bytes) {
  auto now = std::chrono::steady_clock::now();
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  std::int64_t gmp = budget_gmp_bytes() - gmp_bytes_at_start_;
  const std::size_t memory = own_bytes + static_cast<std::size_t>(gmp > 0 ? gmp : 0);

  auto give_up = [&](Status status, const std::string& reason) {
    // Where it was: the stage, then what that stage counts.
    std::string where = *state.stage ? state.stage : "";
    auto add = [&where](const std::string& part) { where += (where.empty() ? "" : ", ") + part; };
    if (state.basis_size || state.pairs_left) {
      add("basis " + std::to_string(state.basis_size) + ", " + std::to_string(state.pairs_left) + " pairs left");
    }
    if (primes_) add(std::to_string(primes_) + (primes_ == 1 ? " prime" : " primes") + " done");
    if (!where.empty()) where = " (" + where + ")";
    // a cancel is the caller's doing, not the engine giving up
    std::string head = status == Status::cancelled ? "cancelled after " + format_seconds(elapsed)
                                                   : "gave up after " + format_seconds(elapsed) + ": " + reason;
    throw BudgetExceeded{status, head + where};
  };
  if (budget_.cancel && budget_.cancel->cancelled()) give_up(Status::cancelled, {});
  if (budget_.time_limit_seconds && elapsed > *budget_.time_limit_seconds) {
    give_up(Status::time_limit, "time limit of " + format_seconds(*budget_.time_limit_seconds) + " reached");
  }
  if (budget_.memory_limit_bytes && memory > *budget_.memory_limit_bytes) {
    give_up(Status::memory_limit, "memory limit of " + format_bytes(*budget_.memory_limit_bytes) +
                                      " reached (" + format_bytes(memory) + " in use)");
  }
  if (budget_.on_progress && now >= next_report_) {
    Progress report = state;
    report.elapsed_seconds = elapsed;
    report.memory_bytes = memory;
    report.primes = primes_;
    budget_.on_progress(report);
    next_report_ = now + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                             std::chrono::duration<double>(budget_.progress_interval_seconds));
  }
}

}  // namespace sdfwb::algebra
