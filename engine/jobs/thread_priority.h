#pragma once
// Background work yields the processor to the interactive thread. On a
// machine with two cores a render keeps every core busy; at equal priority
// the window's thread got its share and no more, and its frames took 24 ms
// (median) while the 100-sphere molecule rendered, against 13 ms with the
// render's threads at a lower priority (docs/large-scenes.md). So the job
// queue's workers take a nice value kBackgroundNiceIncrement higher (a lower
// priority) than the thread that made the queue, and the loop threads that
// work for them take theirs. Linux scheduling priorities are per thread;
// an unprivileged thread can raise its nice value but never lower it again.

namespace sdfwb::jobs {

// How much higher a background thread's nice value is than its creator's.
inline constexpr int kBackgroundNiceIncrement = 10;
// The highest nice value (the lowest priority) Linux has.
inline constexpr int kNicest = 19;

// The calling thread's nice value (-20 most favoured, 19 least).
int threadNice();

// Makes the calling thread at least as nice as `nice` (clamped to kNicest). A
// request to become less nice is ignored: it needs a privilege a desktop
// user does not have, and background work must never outrank the UI anyway.
void becomeAtLeastAsNice(int nice);

// Makes the calling thread a background thread: kBackgroundNiceIncrement
// nicer than it is.
void becomeBackgroundThread();

}  // namespace sdfwb::jobs
