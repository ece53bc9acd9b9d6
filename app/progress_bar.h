#pragma once
// A one-line progress bar on stderr, shown only when stderr is a terminal.

#include <string>

namespace sdfwb::app {

class ProgressBar {
public:
    explicit ProgressBar(std::string label);
    ~ProgressBar();
    void update(int done, int total);

private:
    std::string label_;
    bool enabled_;
    int lastPercent_ = -1;
};

}  // namespace sdfwb::app
