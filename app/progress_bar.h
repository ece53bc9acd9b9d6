#pragma once
// A one-line progress bar on stderr, shown only when stderr is a terminal.

#include <string>

namespace sdfwb::app {

class ProgressBar {
public:
    explicit ProgressBar(std::string label);
    ~ProgressBar();
    void update(int done, int total);
    // With a text after the percentage (what is being done, time left); redrawn
    // whenever the text changes.
    void update(int done, int total, const std::string& detail);

private:
    std::string label_;
    bool enabled_;
    int lastPercent_ = -1;
    std::string lastDetail_;
};

}  // namespace sdfwb::app
