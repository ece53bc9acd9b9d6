#include "app/tradeoff_command.h"

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <thread>

#include <sys/resource.h>

#include "app/backend.h"
#include "app/progress_bar.h"
#include "app/scene_source.h"
#include "app/size_argument.h"
#include "io/atomic_file.h"
#include "scene/scene_json.h"
#include "tradeoff/measurements.h"
#include "tradeoff/plot.h"
#include "tradeoff/report.h"
#include "tradeoff/sweep.h"

namespace sdfwb::app {
namespace {

namespace fs = std::filesystem;

std::atomic<bool> interrupted{false};

extern "C" void onTradeoffInterrupt(int) { interrupted = true; }

// The scene's path as given, "scenes/hard/thin_blade.json" -> "scenes-hard-thin_blade.png"
std::string plotFileName(const std::string& sceneName) {
    std::string name = fs::path(sceneName).replace_extension().string();
    for (char& c : name) {
        if (c == '/' || c == '\\') c = '-';
    }
    while (!name.empty() && (name.front() == '.' || name.front() == '-')) name.erase(name.begin());
    return name + ".png";
}

std::string formatDuration(double seconds) {
    int s = static_cast<int>(seconds + 0.5);
    std::ostringstream out;
    if (s >= 3600) out << s / 3600 << " h ";
    if (s >= 60) out << (s / 60) % 60 << " min ";
    out << s % 60 << " s";
    return out.str();
}

// Timings depend on the machine and on what else runs on it.
std::string machineText() {
    double load[1] = {0};
    std::ostringstream out;
    out << "on " << std::thread::hardware_concurrency() << " hardware threads";
    if (::getloadavg(load, 1) == 1) out << " (load average " << load[0] << " at the start)";
    errno = 0;
    int niceness = ::getpriority(PRIO_PROCESS, 0);
    if (errno == 0) out << ", at niceness " << niceness;
    return out.str();
}

std::string commandText(const TradeoffArguments& a) {
    std::ostringstream out;
    out << "sdf-workbench tradeoff";
    for (const std::string& p : a.paths) out << " " << p;
    out << " --backend " << a.backend << " --size " << a.size << " --repetitions " << a.repetitions;
    if (!a.knobs.empty()) {
        out << " --knobs";
        for (const std::string& k : a.knobs) out << " " << k;
    }
    if (a.budget > 0) out << " --budget " << a.budget;
    out << " --report " << a.report;
    if (!a.plotDir.empty()) out << " --plot-dir " << a.plotDir;
    if (!a.plot.empty()) out << " --plot " << a.plot;
    return out.str();
}

}  // namespace

int runTradeoff(const TradeoffArguments& a) {
    try {
        auto [width, height] = parseSizeArgument(a.size);
        std::vector<tradeoff::KnobRequest> knobs = tradeoff::parseKnobRequests(a.knobs);
        std::vector<fs::path> files = sceneFiles(a.paths);
        if (files.empty()) throw std::runtime_error("no scene files found in " + a.paths.front());
        if (!a.plot.empty() && files.size() != 1) {
            throw std::runtime_error("--plot takes one scene (got " + std::to_string(files.size()) +
                                     "); use --plot-dir for several");
        }
        io::checkCanCreate(a.report);
        if (!a.plot.empty()) io::checkCanCreate(a.plot);
        if (!a.plotDir.empty()) {
            fs::create_directories(a.plotDir);
            io::checkCanCreate(fs::path(a.plotDir) / "plot.png");
        }
        std::vector<tradeoff::SceneInput> scenes;
        for (const fs::path& file : files) {
            scenes.push_back({file.generic_string(), scene::loadSceneFile(file)});
            requireSceneFiles(scenes.back().scene, file.generic_string());
        }

        std::vector<std::unique_ptr<render::Backend>> owned;
        if (a.backend != "gl") owned.push_back(makeBackend(Backend::Cpu));
        if (a.backend != "cpu") owned.push_back(makeBackend(Backend::Gl));
        std::vector<render::Backend*> backends;
        for (auto& b : owned) backends.push_back(b.get());

        tradeoff::SweepOptions options;
        options.width = width;
        options.height = height;
        options.repetitions = a.repetitions;
        if (a.budget > 0) options.budgetSeconds = a.budget;
        options.cacheDir = a.cacheDir.empty() ? tradeoff::defaultCacheDirectory() : fs::path(a.cacheDir);
        options.cancel = &interrupted;
        ProgressBar bar("tradeoff");
        options.progress = [&](const tradeoff::SweepProgress& p) {
            std::string detail = std::to_string(p.scenesDone) + "/" + std::to_string(p.scenesTotal) + " scenes, " +
                                 std::to_string(p.settingsDone) + "/" + std::to_string(p.settingsTotal) + " renders";
            if (p.secondsLeft >= 0) detail += ", about " + formatDuration(p.secondsLeft) + " left";
            bar.update(p.settingsDone, p.settingsTotal, detail + " | " + p.current);
        };
        std::signal(SIGINT, onTradeoffInterrupt);
        std::signal(SIGTERM, onTradeoffInterrupt);

        std::string machine = machineText();
        tradeoff::SweepResult result = tradeoff::runSweep(scenes, knobs, backends, options);
        if (result.cancelled) {
            std::cerr << "sdf-workbench tradeoff: cancelled; no report written\n";
            return 130;
        }

        tradeoff::ReportContext context{commandText(a), machine, {}};
        fs::path reportFolder = fs::absolute(a.report).parent_path();
        for (const tradeoff::SceneResult& scene : result.scenes) {
            if (scene.results.empty()) continue;
            fs::path png = !a.plot.empty()       ? fs::path(a.plot)
                           : !a.plotDir.empty() ? fs::path(a.plotDir) / plotFileName(scene.name)
                                                : fs::path();
            if (png.empty()) continue;
            tradeoff::plotScene(scene, result.backends, png);
            context.plots[scene.name] = fs::relative(fs::absolute(png), reportFolder).generic_string();
        }
        io::writeTextAtomically(a.report, tradeoff::writeReport(result, context));
        if (result.budgetExhausted) {
            int skipped = 0;
            for (const tradeoff::SceneResult& scene : result.scenes) skipped += static_cast<int>(scene.skipped.size());
            std::cerr << "sdf-workbench tradeoff: the budget ran out; " << skipped
                      << " renders skipped (listed in the report)\n";
        }
        std::cout << a.report << "\n";
        return 0;
    } catch (const scene::SceneError& error) {
        for (const std::string& problem : error.problems()) std::cerr << "sdf-workbench tradeoff: " << problem << "\n";
        return 2;
    } catch (const std::invalid_argument& error) {
        std::cerr << "sdf-workbench tradeoff: " << error.what() << "\n";
        return 2;
    } catch (const std::exception& error) {
        std::cerr << "sdf-workbench tradeoff: " << error.what() << "\n";
        return 1;
    }
}

}  // namespace sdfwb::app
