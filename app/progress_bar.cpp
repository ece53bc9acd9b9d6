#include "app/progress_bar.h"

#include <cstdio>

#include <unistd.h>

namespace sdfwb::app {

ProgressBar::ProgressBar(std::string label) : label_(std::move(label)), enabled_(::isatty(STDERR_FILENO) != 0) {}

ProgressBar::~ProgressBar() {
    if (enabled_ && lastPercent_ >= 0) {
        std::fprintf(stderr, "\r\033[K");
        std::fflush(stderr);
    }
}

void ProgressBar::update(int done, int total) { update(done, total, ""); }

void ProgressBar::update(int done, int total, const std::string& detail) {
    if (!enabled_ || total <= 0) {
        return;
    }
    int percent = done * 100 / total;
    if (percent == lastPercent_ && detail == lastDetail_) {
        return;
    }
    lastPercent_ = percent;
    lastDetail_ = detail;
    constexpr int kWidth = 40;
    int filled = percent * kWidth / 100;
    std::string bar(static_cast<size_t>(filled), '#');
    bar.append(static_cast<size_t>(kWidth - filled), '.');
    std::fprintf(stderr, "\r\033[K%s [%s] %3d%%%s%s", label_.c_str(), bar.c_str(), percent, detail.empty() ? "" : " ",
                 detail.c_str());
    std::fflush(stderr);
}

}  // namespace sdfwb::app
