#include "tradeoff/plot.h"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <stdexcept>

#include <plplot.h>

#include "io/atomic_file.h"
#include "tradeoff/analysis.h"

namespace sdfwb::tradeoff {
namespace {

// Errors of 0 cannot sit on a log scale: they are drawn at this floor.
constexpr double kErrorFloor = 1e-3;

// cmap0 entries set below
constexpr PLINT kInk = 1, kGrid = 2, kTolerance = 3, kDefault = 4;
constexpr PLINT kBackendColor[] = {5, 6, 7};
constexpr const char* kBackendSymbol[] = {"●", "▲", "■"};

double logTime(double seconds) { return std::log10(std::max(seconds, 1e-6) * 1000.0); }
double logError(double error) { return std::log10(std::max(error, kErrorFloor)); }

void drawPlot(const SceneResult& scene, const std::vector<std::string>& backends) {
    double x0 = 1e9, x1 = -1e9, y0 = logError(kErrorTolerance), y1 = y0;
    std::vector<BackendAnalysis> analyses;
    for (size_t b = 0; b < backends.size(); ++b) {
        analyses.push_back(analyse(scene, b));
        for (const CostError& p : analyses.back().points) {
            x0 = std::min(x0, logTime(p.cost));
            x1 = std::max(x1, logTime(p.cost));
            y0 = std::min(y0, logError(p.error));
            y1 = std::max(y1, logError(p.error));
        }
    }
    // whole decades around the data, so the log axes get labelled ticks
    x0 = std::floor(x0 - 0.05), x1 = std::ceil(x1 + 0.05), y0 = std::floor(y0 - 0.05), y1 = std::ceil(y1 + 0.05);
    pladv(0);
    plvpor(0.11, 0.70, 0.11, 0.92);  // the legend goes right of the viewport
    plwind(x0, x1, y0, y1);
    plcol0(kGrid);
    pllsty(3);
    plbox("g", 0, 0, "g", 0, 0);
    pllsty(1);
    plcol0(kInk);
    plbox("bcnlst", 0, 0, "bcnlstv", 0, 0);  // l: logarithmic labels
    pllab("median time per frame (ms)", "mean error against the reference (levels of 255)",
          (scene.name + ": " + std::to_string(scene.scene.render.width) + "x" +
           std::to_string(scene.scene.render.height)).c_str());

    PLFLT tx[2] = {x0, x1}, ty[2] = {logError(kErrorTolerance), logError(kErrorTolerance)};
    plcol0(kTolerance);
    pllsty(2);
    plline(2, tx, ty);
    pllsty(1);
    plptex(x0 + 0.02 * (x1 - x0), ty[0] + 0.03 * (y1 - y0), 1, 0, 0, "1/255");

    for (size_t b = 0; b < backends.size(); ++b) {
        const BackendAnalysis& a = analyses[b];
        PLINT color = kBackendColor[b % 3];
        plcol0(color);
        std::vector<PLFLT> xs, ys;
        for (size_t i : a.front) {
            xs.push_back(logTime(a.points[i].cost));
            ys.push_back(logError(a.points[i].error));
        }
        plwidth(2);
        plline(static_cast<PLINT>(xs.size()), xs.data(), ys.data());
        plwidth(1);
        xs.clear(), ys.clear();
        for (const CostError& p : a.points) {
            xs.push_back(logTime(p.cost));
            ys.push_back(logError(p.error));
        }
        plschr(0, 0.7);
        plstring(static_cast<PLINT>(xs.size()), xs.data(), ys.data(), kBackendSymbol[b % 3]);
        plschr(0, 1.0);
        if (b == 0) {
            // name the settings on the front once (the backends' fronts mostly agree)
            plschr(0, 0.6);
            for (size_t i : a.front) {
                plptex(xs[i] + 0.01 * (x1 - x0), ys[i] + 0.015 * (y1 - y0), 1, 0, 0,
                       scene.results[i].setting.label.c_str());
            }
            plschr(0, 1.0);
        }
        if (!a.points.empty()) {
            plcol0(kDefault);
            plschr(0, 1.3);
            plstring(1, &xs[0], &ys[0], "◯");
            plschr(0, 1.0);
        }
    }

    std::vector<std::string> texts;
    std::vector<PLINT> options, textColors, lineColors, lineStyles, symbolColors, symbolNumbers;
    std::vector<PLFLT> lineWidths, symbolScales;
    std::vector<std::string> symbols;
    auto entry = [&](std::string text, PLINT opt, PLINT color, PLINT style, const char* symbol, double scale) {
        texts.push_back(std::move(text));
        options.push_back(opt);
        textColors.push_back(kInk);
        lineColors.push_back(color);
        lineStyles.push_back(style);
        lineWidths.push_back(2);
        symbolColors.push_back(color);
        symbolScales.push_back(scale);
        symbolNumbers.push_back(1);
        symbols.push_back(symbol);
    };
    for (size_t b = 0; b < backends.size(); ++b) {
        entry(backends[b] + " settings, front", PL_LEGEND_LINE | PL_LEGEND_SYMBOL, kBackendColor[b % 3], 1,
              kBackendSymbol[b % 3], 0.7);
    }
    entry("scene default", PL_LEGEND_SYMBOL, kDefault, 1, "◯", 1.3);
    entry("1/255 mean error", PL_LEGEND_LINE, kTolerance, 2, "", 1.0);
    std::vector<const char*> textPointers, symbolPointers;
    for (const std::string& t : texts) textPointers.push_back(t.c_str());
    for (const std::string& s : symbols) symbolPointers.push_back(s.c_str());
    PLFLT width = 0, height = 0;
    plschr(0, 0.7);
    pllegend(&width, &height, PL_LEGEND_BACKGROUND | PL_LEGEND_BOUNDING_BOX, PL_POSITION_RIGHT |
             PL_POSITION_OUTSIDE, 0.02, 0.0, 0.05, 0, kInk, 1, 0, 0, static_cast<PLINT>(texts.size()), options.data(),
             1.0, 1.0, 1.5, 0, textColors.data(), textPointers.data(), nullptr, nullptr, nullptr, nullptr,
             lineColors.data(), lineStyles.data(), lineWidths.data(), symbolColors.data(), symbolScales.data(),
             symbolNumbers.data(), symbolPointers.data());
    plschr(0, 1.0);
}

}  // namespace

void plotScene(const SceneResult& scene, const std::vector<std::string>& backends, const std::filesystem::path& png) {
    // PLplot keeps one global stream state
    static std::mutex plplotMutex;
    std::lock_guard lock(plplotMutex);
    io::writeAtomically(png, [&](const std::filesystem::path& temporary) {
        plsdev("pngcairo");
        plsfnam(temporary.c_str());
        plspage(0, 0, 960, 640, 0, 0);
        plscol0(0, 255, 255, 255);  // background
        plscol0(kInk, 0, 0, 0);
        plscol0(kGrid, 215, 215, 215);
        plscol0(kTolerance, 120, 120, 120);
        plscol0(kDefault, 230, 40, 40);
        plscol0(kBackendColor[0], 30, 90, 200);
        plscol0(kBackendColor[1], 20, 150, 70);
        plscol0(kBackendColor[2], 160, 80, 170);
        plinit();
        drawPlot(scene, backends);
        plend();
        if (!std::filesystem::exists(temporary) || std::filesystem::file_size(temporary) == 0) {
            throw std::runtime_error("cannot write " + png.string() + ": PLplot made no image (driver pngcairo)");
        }
    });
}

}  // namespace sdfwb::tradeoff
