#pragma once
// Data parallelism inside one job: independent indices spread over threads
// (the CPU renderer's tiles, the pruning grid's root cells, the mesher's
// blocks). oneTBB does it in the product. A ThreadSanitizer build runs the
// same loops on plain std::threads instead (SDFWB_PLAIN_THREADS, set by
// -DSDFWB_SANITIZE=thread): Debian's libtbb is not built with TSan, so TSan
// cannot see the synchronisation inside it and reports every tile as a race
// with TBB's own inlined code. Either way the loop bodies are ours and run
// concurrently, which is what TSan is there to check.

#include <functional>

namespace sdfwb::jobs {

// Runs body(i) for every i in [0, count), concurrently, each index once, on
// at most the thread count of the innermost withThreads around the call (the
// machine's by default); returns when all have returned.
void parallelFor(int count, const std::function<void(int)>& body);

// Runs work with parallelFor loops inside it limited to `threads` threads
// (0: the machine's count).
void withThreads(int threads, const std::function<void()>& work);

// The machine's thread count, as parallelFor uses it by default.
int defaultThreads();

}  // namespace sdfwb::jobs
