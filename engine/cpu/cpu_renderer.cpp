#include "cpu/cpu_renderer.h"

#include <mutex>
#include <span>
#include <utility>
#include <vector>

#include "cpu/interpreter.h"
#include "jobs/parallel_for.h"

namespace sdfwb::cpu {

namespace {

// Kernel is f32::Kernel or f64::Kernel.
template <typename Kernel>
bool renderTiles(const program::Program& program, const render::RenderControl& control, image::Frame& frame,
                 const std::function<void(const render::TileRect&)>& onTile) {
    using Source = typename Kernel::SourceType;
    const Kernel kernel(program, control.waitForPruneGrid ? Source::Pruned : Source::PrunedIfBuilt);
    using Real = typename Kernel::Real;
    using vec3 = typename Kernel::Vec3;
    using Scratch = typename Kernel::ScratchType;

    const int width = program.width, height = program.height, aa = program.aa;
    const std::vector<render::TileRect> tiles =
        render::tilesToRender(width, height, control.region, control.tileSize > 0 ? control.tileSize : kDefaultTileSize);
    const int tilesTotal = static_cast<int>(tiles.size());
    std::atomic<int> tilesDone{0};
    std::atomic<bool> cancelled{false};
    std::mutex reportMutex;

    auto renderTile = [&](const render::TileRect& tile) {
        if (control.cancel && control.cancel->load()) {
            cancelled = true;
            return;
        }
        Scratch scratch(program);
        for (int y = tile.y; y < tile.y + tile.h; ++y) {
            for (int x = tile.x; x < tile.x + tile.w; ++x) {
                vec3 sum(Real(0));
                int steps = 0, evaluations = 0, hits = 0;
                float depthSum = 0.0f;  // summed in float, in the GL backend's blending order
                for (int m = 0; m < aa; ++m) {
                    for (int n = 0; n < aa; ++n) {
                        // pixel centres at half-integers, rows counted from the bottom as in GL
                        Real px = Real(x) + Real(0.5) + Kernel::offset(m, aa);
                        Real py = Real(height - 1 - y) + Real(0.5) + Kernel::offset(n, aa);
                        auto result = kernel.trace(scratch, px, py);
                        sum = sum + result.color;
                        steps += result.steps;
                        evaluations += result.evaluations;
                        hits += result.hit ? 1 : 0;
                        depthSum = depthSum + (result.hit ? static_cast<float>(result.t) : 0.0f);
                    }
                }
                vec3 color = sum / Real(aa * aa);
                size_t i = static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x);
                frame.color.rgb[3 * i + 0] = static_cast<float>(color.x);
                frame.color.rgb[3 * i + 1] = static_cast<float>(color.y);
                frame.color.rgb[3 * i + 2] = static_cast<float>(color.z);
                frame.steps[i] = static_cast<float>(steps) / static_cast<float>(aa * aa);
                frame.evaluations[i] = static_cast<float>(evaluations) / static_cast<float>(aa * aa);
                frame.coverage[i] = static_cast<float>(hits) / static_cast<float>(aa * aa);
                frame.depth[i] = hits > 0 ? depthSum / static_cast<float>(hits) : 0.0f;
            }
        }
        int done = ++tilesDone;
        std::lock_guard lock(reportMutex);
        if (onTile) onTile(tile);
        if (control.progress) control.progress(done, tilesTotal);
    };

    jobs::parallelFor(tilesTotal, [&](int t) { renderTile(tiles[t]); });
    return !cancelled.load();
}

}  // namespace

bool renderCpuTiles(const program::Program& program, const render::RenderControl& control, image::Frame& frame,
                    const std::function<void(const render::TileRect&)>& onTile) {
    // The whole render on the caller's thread count: the tiles and the pruning
    // grid the kernel builds first (its own parallel loop) alike; a render
    // that does not wait for the grid leaves its build to the background.
    bool finished = false;
    jobs::withThreads(control.threads, [&] {
        finished = control.precision == render::Precision::Double
                       ? renderTiles<f64::Kernel>(program, control, frame, onTile)
                       : renderTiles<f32::Kernel>(program, control, frame, onTile);
    });
    return finished;
}

render::RenderOutcome renderCpu(const program::Program& program, const render::RenderControl& control) {
    render::RenderOutcome outcome;
    outcome.frame = render::blankFrame(program.width, program.height);
    if (!renderCpuTiles(program, control, outcome.frame, {})) {
        outcome.frame = {};
        outcome.cancelled = true;
    }
    return outcome;
}

double evaluateDistance(const program::Program& program, const glm::dvec3& marchPoint, render::Precision precision) {
    auto evaluate = [&](const auto& kernel) {
        using K = std::decay_t<decltype(kernel)>;
        typename K::ScratchType scratch(program);
        return static_cast<double>(kernel.map(scratch, typename K::Vec3(marchPoint)).d);
    };
    if (precision == render::Precision::Double) {
        return evaluate(f64::Kernel(program, f64::FieldSource::Whole));
    }
    return evaluate(f32::Kernel(program, f32::FieldSource::Whole));
}

}  // namespace sdfwb::cpu
