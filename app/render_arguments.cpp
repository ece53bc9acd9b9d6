#include "app/render_arguments.h"

namespace sdfwb::app {

CLI::App* addRenderCommand(CLI::App& app, RenderArguments& a) {
    CLI::App* render = app.add_subcommand("render", "Render a scene to an image file without a window");
    render->add_option("scene", a.scene, "Scene file (JSON); omit for the built-in default scene");
    render->add_option("-o,--output", a.output, "Output image: .png, .jpg, .tif (8-bit sRGB) or .exr (linear float)")
        ->required();
    render->add_option("--size", a.size, "Image size WIDTHxHEIGHT (default: the scene's render.width x height)");
    render->add_option("--aa", a.aa, "Antialiasing: AA x AA samples per pixel, 1-8 (default: the scene's)")
        ->check(CLI::Range(1, 8));
    render->add_option("--threads", a.threads, "CPU threads (default: all)")->check(CLI::Range(1, 1024));
    render->add_option("--backend", a.backend, "Renderer: cpu (reference) or gl (GLSL, headless through OSMesa)")
        ->check(CLI::IsMember({"cpu", "gl"}));
    render->add_option("--precision", a.precision, "CPU arithmetic: float (matches GL) or double (reference)")
        ->check(CLI::IsMember({"float", "double"}));
    render->add_option("--heat", a.heat, "Also write a step-count heat image to this file");
    render->add_option("--dump-shader", a.dumpShader, "gl backend: write the generated fragment shader to this file");
    render->add_flag("--no-prune", a.noPrune, "Evaluate the whole scene everywhere (a reference for pruning)");
    render->add_flag("--stats", a.stats, "Print render time, steps per pixel and hit ratio (and the GL renderer)");
    return render;
}

}  // namespace sdfwb::app
