#include "jobs/thread_priority.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>

namespace sdfwb::jobs {
int threadNice() {
    // getpriority may return -1 as a value, so errno tells a failure apart
    errno = 0;
    int nice = getpriority(PRIO_PROCESS, static_cast<id_t>(gettid()));
    return errno == 0 ? nice : 0;
}

void becomeAtLeastAsNice(int nice) {
    int wanted = std::min(nice, kNicest);
    if (threadNice() < wanted) setpriority(PRIO_PROCESS, static_cast<id_t>(gettid()), wanted);
}

void becomeBackgroundThread() { becomeAtLeastAsNice(threadNice() + kBackgroundNiceIncrement); }

}  // namespace sdfwb::jobs
