#include "app/render_command.h"

#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "app/command_errors.h"
#include "app/memory_check.h"
#include "app/output_paths.h"
#include "app/progress_bar.h"
#include "app/scene_source.h"
#include "app/size_argument.h"
#include "app/backend.h"
#include "image/image_io.h"
#include "io/atomic_file.h"
#include "jobs/parallel_for.h"
#include "program/compile_scene.h"
#include "scene/scene_json.h"

namespace sdfwb::app {
namespace {

// More threads than the machine has only add overhead; say so rather than
// silently use fewer. 0 stays 0 (all hardware threads).
int clampedThreads(int requested) {
    const int hardware = jobs::defaultThreads();
    if (requested > hardware) {
        std::fprintf(stderr, "sdf-workbench render: --threads %d: this machine runs %d threads at once; using %d\n",
                     requested, hardware, hardware);
        return hardware;
    }
    return requested;
}

}  // namespace

int runRender(const RenderArguments& a) {
    return runReportingErrors("render", [&] {
        // Everything the arguments can get wrong fails here, before any work.
        if (!a.dumpShader.empty() && a.backend != "gl") {
            throw std::invalid_argument("--dump-shader needs --backend gl (the cpu backend runs no shader)");
        }
        for (const std::string& output : {a.output, a.heat}) {
            if (!output.empty()) {
                image::checkWritableFormat(output);
            }
        }
        checkOutputs({{"the scene", a.scene}}, {{"-o", a.output}, {"--heat", a.heat}, {"--dump-shader", a.dumpShader}});
        program::CompileOptions options;
        if (!a.size.empty()) {
            std::tie(options.width, options.height) = parseSizeArgument(a.size);
        }
        options.aa = a.aa;
        options.prune = !a.noPrune;
        BackendRequest request;
        request.backend = a.backend == "gl" ? Backend::Gl : Backend::Cpu;
        request.threads = clampedThreads(a.threads);
        request.precision = a.precision == "double" ? render::Precision::Double : render::Precision::Float;
        request.dumpShader = a.dumpShader;

        scene::Scene scene = loadSceneArgument(a.scene);
        requireSceneFiles(scene, a.scene);
        program::Program program = program::compileScene(scene, options);
        checkRenderFitsInMemory(program.width, program.height);

        ProgressBar bar("rendering");
        request.progress = [&](int done, int total) { bar.update(done, total); };
        BackendResult outcome = renderWithBackend(program, request);
        double seconds = outcome.seconds;

        std::ostringstream settings;
        settings << program.width << "x" << program.height << " aa " << program.aa << ", max steps "
                 << program.trace.maxSteps;
        if (a.backend == "cpu") settings << ", precision " << a.precision;
        image::Metadata metadata = {{"ImageDescription", scene.description},
                                    {"sdfwb:scene", scene.name},
                                    {"sdfwb:backend", a.backend},
                                    {"sdfwb:settings", settings.str()},
                                    {"sdfwb:renderSeconds", std::to_string(seconds)}};
        // The image and its heat map are written together or not at all.
        io::StagedWrites writes;
        image::stageImage(writes, a.output, outcome.frame.color, metadata);
        if (!a.heat.empty()) {
            image::stageImage(writes, a.heat, image::stepHeatImage(outcome.frame, program.trace.maxSteps), metadata);
        }
        writes.commit();
        if (a.stats) {
            image::FrameStats stats = image::frameStats(outcome.frame);
            std::printf("backend %s (%s), %dx%d aa %d\n", a.backend.c_str(),
                        a.backend == "gl" ? outcome.device.c_str() : a.precision.c_str(), program.width,
                        program.height, program.aa);
            if (a.backend == "gl") {
                std::printf("shader compile %.3f s (included in time)\n", outcome.compileSeconds);
            }
            std::printf("time %.3f s, mean steps %.2f, max steps %.0f, mean evaluations %.2f, hit ratio %.4f\n",
                        seconds, stats.meanSteps, stats.maxSteps, stats.meanEvaluations, stats.hitRatio);
        }
        std::printf("%s\n", a.output.c_str());
        return 0;
    });
}

}  // namespace sdfwb::app
