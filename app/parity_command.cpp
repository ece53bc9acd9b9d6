#include "app/parity_command.h"

#include <algorithm>
#include <filesystem>
#include <iostream>

#include "app/backend.h"
#include "app/command_errors.h"
#include "app/output_paths.h"
#include "app/scene_source.h"
#include "app/size_argument.h"
#include "io/atomic_file.h"
#include "parity/parity.h"
#include "scene/scene_json.h"

namespace sdfwb::app {
namespace {

bool isHardCase(const std::filesystem::path& file) {
    return file.parent_path().filename() == "hard";
}

}  // namespace

int runParity(const ParityArguments& a) {
    return runReportingErrors("parity", [&] {
        auto [width, height] = parseSizeArgument(a.size);
        std::vector<std::string> paths = a.paths.empty() ? std::vector<std::string>{"scenes"} : a.paths;
        auto files = sceneFiles(paths);
        if (files.empty()) {
            throw std::runtime_error("no scene files found in " + paths.front());
        }
        std::vector<NamedPath> inputs;
        for (const auto& file : files) inputs.push_back({"the scene", file.string()});
        checkOutputs(inputs, {{"--report", a.report}});
        std::unique_ptr<render::Backend> cpu = makeBackend(Backend::Cpu), gl = makeBackend(Backend::Gl);
        bool anyHard = std::any_of(files.begin(), files.end(), isHardCase);
        std::string table = parity::tableHeader(anyHard);
        std::cout << "GL renderer: " << gl->device() << "\n" << table << std::flush;
        bool allPass = true;
        std::string polynomialNotes;
        for (const auto& file : files) {
            scene::Scene scene = scene::loadSceneFile(file);
            requireSceneFiles(scene, file.string());
            parity::ParityOptions options{.width = width, .height = height, .aa = a.aa, .reference = isHardCase(file)};
            std::optional<scene::Scene> intended = options.reference ? parity::loadIntendedScene(file) : std::nullopt;
            options.intended = intended ? &*intended : nullptr;
            parity::ParityResult result = parity::measureParity(scene, *cpu, *gl, options);
            std::string name = std::filesystem::relative(file).string();
            std::string row = parity::tableRow(name, result, anyHard);
            std::cout << row << std::flush;
            table += row;
            if (result.cpuPolynomial && result.glPolynomial) {
                polynomialNotes += parity::describeAccuracy(name + " CPU vs first-root reference", *result.cpuPolynomial) + "\n" +
                                   parity::describeAccuracy(name + " GL vs first-root reference", *result.glPolynomial) + "\n";
            }
            allPass = allPass && (options.reference ? result.passesHardGate : result.passes);
        }
        if (!polynomialNotes.empty()) {
            std::cout << "\n" << polynomialNotes;
        }
        if (!a.report.empty()) {
            io::writeTextAtomically(a.report, "GL renderer: " + gl->device() + "\n\n" + table +
                                                  (polynomialNotes.empty() ? "" : "\n" + polynomialNotes));
        }
        return allPass ? 0 : kExitCheckFailed;
    });
}

}  // namespace sdfwb::app
