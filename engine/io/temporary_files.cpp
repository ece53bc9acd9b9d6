#include "io/temporary_files.h"

#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <string>

#include <signal.h>
#include <unistd.h>

namespace sdfwb::io {
namespace {

// Fixed storage: the signal handler may only read plain memory and call unlink.
constexpr int kSlots = 32;
constexpr std::size_t kPathBytes = 4096;
struct Slot {
    std::atomic<bool> used{false};
    std::atomic<bool> ready{false};  // the path is complete
    char path[kPathBytes];
};
std::array<Slot, kSlots> slots;

constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};

extern "C" void removeRegistered() {
    for (Slot& slot : slots) {
        if (slot.ready.load()) {
            ::unlink(slot.path);
        }
    }
}

extern "C" void removeAndReraise(int signal) {
    removeRegistered();
    struct sigaction action {};
    action.sa_handler = SIG_DFL;
    sigemptyset(&action.sa_mask);
    ::sigaction(signal, &action, nullptr);
    ::raise(signal);
}

}  // namespace

void removeTemporariesOnTermination() {
    static std::atomic<bool> installed{false};
    if (installed.exchange(true)) {
        return;
    }
    // A library that calls exit() from inside a write (libjpeg on a full disk)
    // must not leave its temporary file behind either.
    std::atexit(removeRegistered);
    for (int signal : kSignals) {
        struct sigaction previous {};
        ::sigaction(signal, nullptr, &previous);
        if (previous.sa_handler == SIG_IGN) {
            continue;  // nohup and friends: keep ignoring
        }
        struct sigaction action {};
        action.sa_handler = removeAndReraise;
        sigemptyset(&action.sa_mask);
        ::sigaction(signal, &action, nullptr);
    }
}

TemporaryFile::TemporaryFile(const std::filesystem::path& path) {
    const std::string& text = path.native();
    if (text.size() >= kPathBytes) {
        return;
    }
    for (int i = 0; i < kSlots; ++i) {
        bool expected = false;
        if (slots[i].used.compare_exchange_strong(expected, true)) {
            std::memcpy(slots[i].path, text.c_str(), text.size() + 1);
            slots[i].ready.store(true);
            slot_ = i;
            return;
        }
    }
}

TemporaryFile::~TemporaryFile() {
    if (slot_ >= 0) {
        slots[slot_].ready.store(false);
        slots[slot_].used.store(false);
    }
}

void removeStaleTemporaries(const std::filesystem::path& destination) {
    std::filesystem::path folder = destination.parent_path().empty() ? "." : destination.parent_path();
    const std::string prefix = destination.stem().string() + ".tmp-";
    const std::string extension = destination.extension().string();
    std::error_code error;
    for (std::filesystem::directory_iterator it(folder, error), end; !error && it != end; it.increment(error)) {
        const std::string name = it->path().filename().string();
        if (name.size() <= prefix.size() + extension.size() || name.compare(0, prefix.size(), prefix) != 0 ||
            name.compare(name.size() - extension.size(), extension.size(), extension) != 0) {
            continue;
        }
        // "<stem>.tmp-<pid>-<n><ext>"
        const std::string middle = name.substr(prefix.size(), name.size() - prefix.size() - extension.size());
        const std::size_t dash = middle.find('-');
        if (dash == 0 || dash == std::string::npos ||
            middle.find_first_not_of("0123456789-") != std::string::npos) {
            continue;
        }
        const long pid = std::strtol(middle.substr(0, dash).c_str(), nullptr, 10);
        if (pid > 0 && pid != ::getpid() && ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH) {
            std::error_code ignored;
            std::filesystem::remove(it->path(), ignored);
        }
    }
}

}  // namespace sdfwb::io
