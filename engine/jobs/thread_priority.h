#pragma once
// Background work yields the processor to the interactive thread. On a
// machine with two cores a render keeps every core busy; at equal priority
// the UI thread got a third of one and the window's frame time rose from 13
// to 36 ms while the molecule refined. Threads that run background work
// (the job queue's workers, and loop helpers working for them) therefore run
// at a higher nice value than the thread that started the program. Linux
// scheduling priorities are per thread; an unprivileged thread can raise its
// nice value but never lower it again.

namespace sdfwb::jobs {

// How much nicer background threads are than the threads that start them.
inline constexpr int kBackgroundNiceIncrement = 10;

// The calling thread's nice value (-20 most favoured, 19 least).
int threadNice();

// Makes the calling thread at least as nice as `nice` (clamped to 19). A
// request to become less nice is ignored: it needs a privilege a desktop
// user does not have, and background work must never outrank the UI anyway.
void becomeAtLeastAsNice(int nice);

// Makes the calling thread a background thread: kBackgroundNiceIncrement
// nicer than it is.
void becomeBackgroundThread();

}  // namespace sdfwb::jobs
