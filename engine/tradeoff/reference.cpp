#include "tradeoff/reference.h"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>

#include "cpu/cpu_renderer.h"
#include "io/atomic_file.h"
#include "parity/reference_scene.h"
#include "program/compile_scene.h"
#include "scene/scene_json.h"
#include "tradeoff/cache_key.h"

namespace sdfwb::tradeoff {
namespace {

constexpr char kMagic[8] = {'S', 'D', 'F', 'W', 'R', 'E', 'F', '2'};

std::filesystem::path cacheFile(const std::filesystem::path& dir, const std::string& key) {
    return dir / (key + ".ref");
}

void writeFloats(std::ostream& out, const std::vector<float>& v) {
    out.write(reinterpret_cast<const char*>(v.data()), static_cast<std::streamsize>(v.size() * sizeof(float)));
}

bool readFloats(std::istream& in, std::vector<float>& v, size_t count) {
    v.resize(count);
    in.read(reinterpret_cast<char*>(v.data()), static_cast<std::streamsize>(count * sizeof(float)));
    return static_cast<size_t>(in.gcount()) == count * sizeof(float);
}

}  // namespace

scene::Scene referenceScene(const scene::Scene& scene, const ReferenceOptions& options) {
    scene::Scene tight = parity::referenceScene(scene, options.tightening);
    tight.render.aa = std::max(tight.render.aa, options.minimumAa);
    // every bounce a sweep may ask for (the max_depth and ray_weight_cutoff
    // knobs); the parity gate's reference keeps the scene's own ray tree
    tight.render.maxDepth = scene::kMaxTraceDepth;
    tight.render.rayWeightCutoff /= options.tightening;
    return tight;
}

std::string referenceKey(const scene::Scene& referenceScene, std::string_view shadingCode) {
    scene::Scene keyed = referenceScene;
    keyed.name.clear();
    keyed.description.clear();
    return cacheKey(keyed, shadingCode);
}

std::optional<image::Frame> loadReference(const std::filesystem::path& cacheDir, const std::string& key, int width,
                                          int height) {
    std::ifstream in(cacheFile(cacheDir, key), std::ios::binary);
    if (!in) return std::nullopt;
    char magic[sizeof kMagic];
    std::int32_t size[2];
    in.read(magic, sizeof magic);
    in.read(reinterpret_cast<char*>(size), sizeof size);
    if (!in || std::memcmp(magic, kMagic, sizeof kMagic) != 0 || size[0] != width || size[1] != height) {
        return std::nullopt;
    }
    image::Frame frame;
    frame.color = image::Image(width, height);
    size_t pixels = frame.color.pixelCount();
    if (!readFloats(in, frame.color.rgb, 3 * pixels) || !readFloats(in, frame.steps, pixels) ||
        !readFloats(in, frame.evaluations, pixels) || !readFloats(in, frame.coverage, pixels) ||
        !readFloats(in, frame.depth, pixels) || in.peek() != EOF) {
        return std::nullopt;
    }
    return frame;
}

void storeReference(const std::filesystem::path& cacheDir, const std::string& key, const image::Frame& frame) {
    std::error_code error;
    std::filesystem::create_directories(cacheDir, error);
    if (error) throw std::runtime_error("cannot create " + cacheDir.string() + ": " + error.message());
    std::ostringstream out(std::ios::binary);
    out.write(kMagic, sizeof kMagic);
    std::int32_t size[2] = {frame.color.width, frame.color.height};
    out.write(reinterpret_cast<const char*>(size), sizeof size);
    writeFloats(out, frame.color.rgb);
    writeFloats(out, frame.steps);
    writeFloats(out, frame.evaluations);
    writeFloats(out, frame.coverage);
    writeFloats(out, frame.depth);
    io::writeTextAtomically(cacheFile(cacheDir, key), out.str());
}

std::optional<ReferenceFrame> obtainReference(const scene::Scene& referenceScene, const std::filesystem::path& cacheDir,
                                              const std::atomic<bool>* cancel) {
    std::string key = referenceKey(referenceScene);
    int width = referenceScene.render.width, height = referenceScene.render.height;
    if (std::optional<image::Frame> cached = loadReference(cacheDir, key, width, height)) {
        return ReferenceFrame{std::move(*cached), true, 0};
    }
    program::Program program = program::compileScene(referenceScene);
    render::RenderControl control;
    control.precision = render::Precision::Double;
    control.cancel = cancel;
    auto start = std::chrono::steady_clock::now();
    render::RenderOutcome outcome = cpu::renderCpu(program, control);
    if (outcome.cancelled) return std::nullopt;
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    storeReference(cacheDir, key, outcome.frame);
    return ReferenceFrame{std::move(outcome.frame), false, seconds};
}

}  // namespace sdfwb::tradeoff
