#include "app/memory_check.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>

#include <sys/resource.h>
#include <unistd.h>

namespace sdfwb::app {
namespace {

std::string gigabytes(std::size_t bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f GB", static_cast<double>(bytes) / 1e9);
    return text;
}

}  // namespace

std::size_t availableMemoryBytes() {
    std::size_t available = static_cast<std::size_t>(::sysconf(_SC_PHYS_PAGES)) *
                            static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));
    std::ifstream meminfo("/proc/meminfo");
    std::string key;
    std::size_t kilobytes = 0;
    while (meminfo >> key >> kilobytes) {
        if (key == "MemAvailable:") {
            available = kilobytes * 1024;
            break;
        }
        meminfo.ignore(64, '\n');
    }
    rlimit limit{};
    if (::getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY) {
        available = std::min(available, static_cast<std::size_t>(limit.rlim_cur));
    }
    return available;
}

void checkRenderFitsInMemory(int width, int height) {
    const std::size_t needed =
        static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * kRenderBytesPerPixel;
    const std::size_t available = availableMemoryBytes();
    if (needed > available) {
        throw std::invalid_argument("the image is " + std::to_string(width) + "x" + std::to_string(height) +
                                    " pixels: rendering it needs about " + gigabytes(needed) + ", " +
                                    gigabytes(available) + " of memory are available");
    }
}

}  // namespace sdfwb::app
