#pragma once
// The GLSL backend: renders a Program with the OpenGL 3.3 core context that is
// current on the calling thread, into float framebuffers, in tiles and one pass
// per AA sub-sample (so no draw call grows with image size or AA), and reads
// back a Frame laid out exactly as the CPU backend's.
//
// Shaders depend only on the program's structure: programs are cached by
// Program::structureKey(), parameter edits only re-upload the parameter buffer
// and uniforms. The counters let tests assert that.

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "glcontext/gl_functions.h"
#include "glcontext/gl_object.h"
#include "image/image.h"
#include "image/mipmapped_images.h"
#include "program/program.h"
#include "program/scene_images.h"
#include "render/render_control.h"

namespace sdfwb::gl {

struct GlCounters {
    int generations = 0;        // fragment shaders generated
    int compiles = 0;           // programs compiled and linked
    int cacheHits = 0;          // renders that found their program cached
    double lastCompileSeconds = 0;
};

constexpr int kDefaultTileSize = 256;  // pixels per side of one draw, when the control says 0

class GlRenderer {
public:
    // `gl` is the current context's table; every call must run with that
    // context (or one sharing its objects, for cached programs) current.
    explicit GlRenderer(const glcontext::GlFunctions& gl);
    ~GlRenderer();
    GlRenderer(const GlRenderer&) = delete;
    GlRenderer& operator=(const GlRenderer&) = delete;

    // Makes sure the shader for the program's structure is built. Throws
    // glcontext::GlError whose message holds the build report, with line
    // numbers of the generated source (see generateFragmentShader).
    void prepare(const program::Program& program);
    // prepare(), then a draw of a few pixels with the state real renders use,
    // so that llvmpipe's code generation at the first draw happens here too.
    void warmUp(const program::Program& program);

    // The whole frame (GlProgressiveRender run to the end); control.threads
    // and control.precision do not apply.
    render::RenderOutcome render(const program::Program& program, const render::RenderControl& control = {});

    const GlCounters& counters() const { return counters_; }
    const glcontext::GlFunctions& functions() const { return gl_; }

    // --- Handing programs between sharing contexts ---
    // A worker renderer builds (and warms up) a program in its own context; the
    // UI thread's renderer adopts it, so the UI never waits on a compile.
    bool hasProgram(const program::Program& program) const;
    // Removes the built program for `program`'s structure from this cache and
    // returns it (empty if none). Call glFinish (or fence) before handing over.
    glcontext::GlObject releaseProgram(const program::Program& program);
    // Caches a linked program built for `program`'s structure by a context
    // sharing objects with this one (counts neither a generation nor a compile).
    void adoptProgram(const program::Program& program, glcontext::GlObject linked);

    // --- Draw-by-draw rendering (gl/progressive_render.h) ---
    // Uses the program for `program`'s structure (building it if needed),
    // uploads its parameters and binds what a draw needs.
    void bindForDrawing(const program::Program& program);
    // One full-screen pass of sub-sample (m, n) into the bound framebuffer,
    // within the current viewport and scissor, added to what is there.
    void drawSubsample(int m, int n);
    // Sets the blend and scissor state draws need (on) or restores it (off).
    void setDrawState(bool on);

    // Whether a draw waits for the program's prune grid (the default) or,
    // while it is built in the background, draws with one cell keeping
    // everything (the window: nothing slow on the UI thread).
    void setWaitForGrid(bool wait) { waitForGrid_ = wait; }

private:
    struct CachedProgram;
    bool waitForGrid_ = true;
    const CachedProgram& programFor(const program::Program& program);
    void uploadParameters(const program::Program& program, const CachedProgram& cached);
    // Uploads the scene images' texels, environment first, unless they are
    // the ones last uploaded.
    void uploadImages(const program::ResolvedImages& images);
    const CachedProgram* bound_ = nullptr;

    glcontext::GlFunctions gl_;
    std::map<std::uint64_t, std::unique_ptr<CachedProgram>> cache_;
    glcontext::GlObject paramBuffer_;
    glcontext::GlObject paramTexture_;
    glcontext::GlObject vertexArray_;
    glcontext::GlObject texelBuffer_;
    glcontext::GlObject texelTexture_;
    std::vector<std::shared_ptr<const image::MipmappedImages>> uploadedImages_;
    // a fold loop's prune-grid inputs (shader_generator.cpp): nodes, spans, blocks
    glcontext::GlObject foldBuffers_[3];
    glcontext::GlObject foldTextures_[3];
    GlCounters counters_;
};

}  // namespace sdfwb::gl
