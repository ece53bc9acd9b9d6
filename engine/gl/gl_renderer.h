#pragma once
// The GLSL backend: renders a Program with the OpenGL 3.3 core context that is
// current on the calling thread, into float framebuffers, in tiles and one pass
// per AA sub-sample (so no draw call grows with image size or AA), and reads
// back a Frame laid out exactly as the CPU backend's.
//
// Shaders depend only on the program's structure: programs are cached by
// Program::structureKey(), parameter edits only re-upload the parameter buffer
// and uniforms. The counters let tests assert that.

#include <atomic>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>

#include "glcontext/gl_functions.h"
#include "glcontext/gl_object.h"
#include "image/image.h"
#include "program/program.h"

namespace sdfwb::gl {

struct GlCounters {
    int generations = 0;        // fragment shaders generated
    int compiles = 0;           // programs compiled and linked
    int cacheHits = 0;          // renders that found their program cached
    double lastCompileSeconds = 0;
};

struct GlRenderControl {
    int tileSize = 256;  // pixels per side of one draw call
    const std::atomic<bool>* cancel = nullptr;  // checked between draws
    std::function<void(int drawsDone, int drawsTotal)> progress;
};

struct GlRenderOutcome {
    image::Frame frame;
    bool cancelled = false;
};

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

    GlRenderOutcome render(const program::Program& program, const GlRenderControl& control = {});

    const GlCounters& counters() const { return counters_; }

private:
    struct CachedProgram;
    const CachedProgram& programFor(const program::Program& program);
    void uploadParameters(const program::Program& program, const CachedProgram& cached);

    glcontext::GlFunctions gl_;
    std::map<std::uint64_t, std::unique_ptr<CachedProgram>> cache_;
    glcontext::GlObject paramBuffer_;
    glcontext::GlObject paramTexture_;
    glcontext::GlObject vertexArray_;
    GlCounters counters_;
};

}  // namespace sdfwb::gl
