#pragma once
// A ScriptHost for tests that run scripts without a window: always idle,
// screenshots and files accepted and not written, a fixed view size.

#include <filesystem>
#include <string>
#include <utility>

#include "ui/script.h"

namespace sdfwb::ui {

struct StillScriptHost : ScriptHost {
    std::pair<int, int> size{0, 0};
    PolynomialPanelState polynomial;

    bool idle() const override { return true; }
    std::string requestScreenshot(const std::filesystem::path&) override { return ""; }
    std::string save(const std::filesystem::path&) override { return ""; }
    std::string open(const std::filesystem::path&) override { return ""; }
    void quit() override {}
    PolynomialPanelState& polynomialPanel() override { return polynomial; }
    std::pair<int, int> viewSize() const override { return size; }
};

}  // namespace sdfwb::ui
