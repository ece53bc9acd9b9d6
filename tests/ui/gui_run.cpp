#include "gui_run.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include "support/sanitizers.h"
#include "support/source_tree.h"

namespace sdfwb::test {

namespace fs = std::filesystem;

std::string readAll(const fs::path& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

fs::path makeGuiFolder(const std::string& name, const std::string& script) {
    fs::path dir = fs::path(sdfwb::test::outputDir()) / name;
    fs::remove_all(dir);
    fs::create_directories(dir / "config");
    fs::create_directories(dir / "state");
    std::ofstream(dir / "script.txt") << script;
    return dir;
}

namespace {

// The ASan runtime this test runs with when it is a shared library (GCC's
// libasan; clang links its own into the executable): "" otherwise.
std::string sharedAsanRuntime() {
    std::ifstream maps("/proc/self/maps");
    for (std::string line; std::getline(maps, line);) {
        const std::size_t path = line.find('/');
        if (path != std::string::npos && line.find("/libasan.so", path) != std::string::npos) return line.substr(path);
    }
    return "";
}

// Under AddressSanitizer the workbench runs with Mesa's DRI driver preloaded.
// When the window closes, Mesa unloads the driver while two 56-byte blocks
// are still reachable only from the driver's globals; unloaded, they look
// leaked to LeakSanitizer, at an address that no module owns any more (so no
// suppression can name it; traced to swrast_dri.so with LD_DEBUG=files).
// Preloaded, the driver stays mapped to the end of the process, as in any
// run that does not unload it. A shared ASan runtime must come first.
std::string leakCheckPreload() {
    const std::string driver = SDFWB_SWRAST_DRI;
    if (!kAddressSanitizer || driver.empty() || driver.ends_with("NOTFOUND")) return "";
    const std::string runtime = sharedAsanRuntime();
    return "env LD_PRELOAD='" + (runtime.empty() ? driver : runtime + ":" + driver) + "' ";
}

}  // namespace

std::string guiShellCommand(const fs::path& dir, const std::string& arguments, bool printPid) {
    std::string workbench = leakCheckPreload() + "'" + SDFWB_WORKBENCH + "' gui " + arguments;
    // the shell prints its id, then becomes the workbench (same process)
    std::string run = printPid ? "sh -c 'echo $$; exec \"$0\" \"$@\"' " + workbench : workbench;
    return "cd '" + dir.string() + "' && env XDG_CONFIG_HOME='" + (dir / "config").string() + "' XDG_STATE_HOME='" +
           (dir / "state").string() + "' xvfb-run -a -s '-screen 0 1280x800x24' " + run;
}

void runGuiScript(const fs::path& dir) {
    int status = std::system((guiShellCommand(dir, "--script script.txt") + " > run.log 2>&1").c_str());
    EXPECT_EQ(status, 0) << "the workbench failed:\n" << readAll(dir / "run.log");
}

namespace {

// Where the viewport shows the scene at 1280x800 (left of the 390-pixel side
// column), below the statistics overlay and above the status bar.
struct Crop {
    int x0, y0, x1, y1;
};
Crop viewportCrop(const image::Image& shot) {
    return {shot.width * 5 / 100, shot.height * 30 / 100, shot.width * 65 / 100, shot.height * 90 / 100};
}

}  // namespace

double meanDifference(const image::Image& a, const image::Image& b) {
    Crop c = viewportCrop(a);
    double sum = 0;
    size_t count = 0;
    for (int y = c.y0; y < c.y1; ++y) {
        for (int x = c.x0; x < c.x1; ++x) {
            for (size_t ch = 0; ch < 3; ++ch) {
                size_t i = (static_cast<size_t>(y) * static_cast<size_t>(a.width) + static_cast<size_t>(x)) * 3 + ch;
                sum += std::abs(a.rgb[i] - b.rgb[i]) * 255.0;
                ++count;
            }
        }
    }
    return sum / static_cast<double>(count);
}

double contrast(const image::Image& shot) {
    Crop c = viewportCrop(shot);
    double sum = 0, squares = 0;
    size_t count = 0;
    for (int y = c.y0; y < c.y1; ++y) {
        for (int x = c.x0; x < c.x1; ++x) {
            size_t i = (static_cast<size_t>(y) * static_cast<size_t>(shot.width) + static_cast<size_t>(x)) * 3;
            double v = (shot.rgb[i] + shot.rgb[i + 1] + shot.rgb[i + 2]) / 3.0;
            sum += v;
            squares += v * v;
            ++count;
        }
    }
    double mean = sum / static_cast<double>(count);
    return std::sqrt(std::max(0.0, squares / static_cast<double>(count) - mean * mean));
}

void GuiTest::SetUp() {
    if (std::system("xvfb-run -a true > /dev/null 2>&1") == 0) return;
    const char* required = std::getenv("SDFWB_REQUIRE_GL");
    if (required && std::string(required) == "1") {
        GTEST_FAIL() << "no X server could start (xvfb-run -a true failed), and SDFWB_REQUIRE_GL=1";
    }
    GTEST_SKIP() << "no X server could start (xvfb-run -a true failed)";
}

}  // namespace sdfwb::test
