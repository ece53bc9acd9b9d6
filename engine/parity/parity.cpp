#include "parity/parity.h"

#include <chrono>
#include <cmath>
#include <cstdio>

#include "image/image_io.h"
#include "parity/reference_scene.h"
#include "program/compile_scene.h"
#include "scene/scene_json.h"

namespace sdfwb::parity {
namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

ParityResult measureParity(const scene::Scene& scene, render::Backend& cpu, render::Backend& gl,
                           const ParityOptions& options) {
    program::CompileOptions compileOptions{options.width, options.height, options.aa};
    program::Program program = program::compileScene(scene, compileOptions);
    ParityResult result;

    auto start = std::chrono::steady_clock::now();
    render::RenderOutcome cpuFrame = cpu.render(program);
    result.cpuSeconds = secondsSince(start);

    gl.prepare(program);  // shader build is not part of the render time
    start = std::chrono::steady_clock::now();
    render::RenderOutcome glFrame = gl.render(program);
    result.glSeconds = secondsSince(start);

    image::FrameStats cpuStats = image::frameStats(cpuFrame.frame), glStats = image::frameStats(glFrame.frame);
    result.cpuHitRatio = cpuStats.hitRatio;
    result.glHitRatio = glStats.hitRatio;
    result.cpuNonFinite = cpuStats.nonFinite;
    result.glNonFinite = glStats.nonFinite;
    result.glVsCpu = image::compareImages(glFrame.frame.color, cpuFrame.frame.color);
    result.cpuColor = cpuFrame.frame.color;
    result.glColor = glFrame.frame.color;
    result.passes = image::passes(result.glVsCpu, image::kParityThresholds);

    if (options.reference) {
        const scene::Scene& intended = options.intended ? *options.intended : scene;
        render::RenderControl doublePrecision;
        doublePrecision.precision = render::Precision::Double;
        render::RenderOutcome exact = cpu.render(program::compileScene(intended, compileOptions), doublePrecision);
        // an intended result is another construction: its march takes other
        // steps, and sharp edges of the image move by a fraction of a pixel
        bool colourEdges = options.intended != nullptr;
        result.cpuAgreement = compareWithReference(cpuFrame.frame, exact.frame, colourEdges);
        result.glAgreement = compareWithReference(glFrame.frame, exact.frame, colourEdges);
        program::Program referenceProgram =
            program::compileScene(referenceScene(intended, options.referenceTightening), compileOptions);
        render::RenderOutcome reference = cpu.render(referenceProgram, doublePrecision);
        result.hasReference = true;
        result.intendedReference = options.intended != nullptr;
        result.cpuConverged = compareWithReference(cpuFrame.frame, reference.frame, true);
        result.glConverged = compareWithReference(glFrame.frame, reference.frame, true);
        result.referenceHitRatio = image::frameStats(reference.frame).hitRatio;
        result.cpuVsReference = image::compareImages(cpuFrame.frame.color, reference.frame.color);
        result.glVsReference = image::compareImages(glFrame.frame.color, reference.frame.color);
        result.passesHardGate = hardGate(result);
    }

    if (polynomialScene(scene)) {
        program::Program single = program::compileScene(scene, {options.width, options.height, 1});
        std::vector<std::optional<double>> reference = referenceDepths(scene, options.width, options.height);
        result.cpuPolynomial = measureAccuracy(reference, cpu.render(single).frame);
        result.glPolynomial = measureAccuracy(reference, gl.render(single).frame);
    }
    return result;
}

std::optional<scene::Scene> loadIntendedScene(const std::filesystem::path& hardScene) {
    std::filesystem::path intended = hardScene.parent_path() / "intended" / hardScene.filename();
    if (!std::filesystem::is_regular_file(intended)) return std::nullopt;
    return scene::loadSceneFile(intended);
}

namespace {

bool agrees(const ReferenceAgreement& a, const HardGateThresholds& t) {
    return a.interiorErrorPercent <= t.interiorErrorPercent && a.interiorMaskPercent <= t.interiorMaskPercent &&
           a.silhouetteMaskPercent <= t.silhouetteMaskPercent;
}

}  // namespace

bool hardGate(const ParityResult& r) {
    if (r.cpuNonFinite > 0 || r.glNonFinite > 0) return false;
    if (!r.passes) return false;
    if (!agrees(r.cpuAgreement, kHardGateThresholds) || !agrees(r.glAgreement, kHardGateThresholds)) return false;
    return r.glVsReference.meanAbs <= 1.25 * r.cpuVsReference.meanAbs + 1.0;
}

std::vector<std::filesystem::path> writeFailureImages(const ParityResult& result, const std::filesystem::path& folder,
                                                      const std::string& name) {
    std::filesystem::create_directories(folder);
    std::vector<std::filesystem::path> paths = {folder / (name + "-expected.png"), folder / (name + "-actual.png"),
                                                folder / (name + "-diff.png")};
    image::writeImage(paths[0], result.cpuColor);
    image::writeImage(paths[1], result.glColor);
    image::writeImage(
        paths[2], image::differenceHeatImage(result.glColor, result.cpuColor, image::kParityThresholds.hardFailLevel));
    return paths;
}

std::string tableHeader(bool withReference) {
    std::string header =
        "| scene | max err | mean err | % > 1/255 | % > 8/255 | CPU s | GL s | GL/CPU | parity |";
    std::string rule = "|---|---|---|---|---|---|---|---|---|";
    if (withReference) {
        header += " CPU vs ref (mean) | GL vs ref (mean) | hit ref / cpu / gl | silhouette % | interior % > 8/255 cpu / gl"
                  " | interior mask % cpu / gl | silhouette mask % cpu / gl | vs ref % > 8/255 off edges cpu / gl | hard gate |";
        rule += "---|---|---|---|---|---|---|---|---|";
    }
    return header + "\n" + rule + "\n";
}

std::string tableRow(const std::string& name, const ParityResult& r, bool withReference) {
    char buffer[512];
    std::snprintf(buffer, sizeof buffer, "| %s | %.0f | %.4f | %.3f | %.3f | %.3f | %.3f | %.2f | %s |", name.c_str(),
                  r.glVsCpu.maxAbs, r.glVsCpu.meanAbs, r.glVsCpu.percentAbove1, r.glVsCpu.percentAbove8, r.cpuSeconds,
                  r.glSeconds, r.cpuSeconds > 0 ? r.glSeconds / r.cpuSeconds : 0.0, r.passes ? "pass" : "FAIL");
    std::string row = buffer;
    if (withReference && r.hasReference) {
        std::snprintf(buffer, sizeof buffer,
                      " %.4f | %.4f | %.4f / %.4f / %.4f%s | %.2f | %.3f / %.3f | %.3f / %.3f | %.3f / %.3f | %.3f / %.3f | %s |",
                      r.cpuVsReference.meanAbs, r.glVsReference.meanAbs, r.referenceHitRatio, r.cpuHitRatio,
                      r.glHitRatio, r.intendedReference ? " (intended)" : "", r.cpuAgreement.silhouettePercent,
                      r.cpuAgreement.interiorErrorPercent, r.glAgreement.interiorErrorPercent,
                      r.cpuAgreement.interiorMaskPercent, r.glAgreement.interiorMaskPercent,
                      r.cpuAgreement.silhouetteMaskPercent, r.glAgreement.silhouetteMaskPercent,
                      r.cpuConverged.interiorErrorPercent, r.glConverged.interiorErrorPercent,
                      r.passesHardGate ? "pass" : "FAIL");
        row += buffer;
    } else if (withReference) {
        row += " | | | | | | | | |";
    }
    return row + "\n";
}

}  // namespace sdfwb::parity
