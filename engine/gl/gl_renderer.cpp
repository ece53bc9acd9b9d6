#include "gl/gl_renderer.h"

#include <chrono>
#include <vector>

#include "gl/shader_generator.h"
#include "glcontext/gl_debug.h"
#include "glcontext/shader_program.h"

namespace sdfwb::gl {

using glcontext::GlError;

struct GlRenderer::CachedProgram {
    glcontext::GlObject program;
    std::map<std::string, GLint> uniforms;

    GLint uniform(const std::string& name) const {
        auto it = uniforms.find(name);
        return it == uniforms.end() ? -1 : it->second;
    }
};

namespace {

const char* const kUniformNames[] = {
    "uParams", "uCameraOrigin", "uCameraForward", "uCameraRight", "uCameraUp", "uTanHalfFov", "uResolution",
    "uSubsample", "uAA", "uMaxSteps", "uMaxDistance", "uEpsilon", "uEpsilonPerDistance", "uShadowMode",
    "uShadowSteps", "uAoSamples", "uAoDistance", "uLightingModel", "uLightCount", "uAmbientLight", "uBackground",
    "uLightDirection", "uLightColor", "uLightSoftness"};

// A pair of RGBA32F textures (colour sum, statistics sum) in one framebuffer.
struct Targets {
    glcontext::GlObject framebuffer, color, stats;
};

Targets makeTargets(const glcontext::GlFunctions& gl, int width, int height) {
    Targets t{glcontext::makeFramebuffer(gl), glcontext::makeTexture(gl), glcontext::makeTexture(gl)};
    for (GLuint texture : {t.color.get(), t.stats.get()}) {
        gl.BindTexture(GL_TEXTURE_2D, texture);
        gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width, height, 0, GL_RGBA, GL_FLOAT, nullptr);
        gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    }
    gl.BindTexture(GL_TEXTURE_2D, 0);
    gl.BindFramebuffer(GL_FRAMEBUFFER, t.framebuffer.get());
    gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, t.color.get(), 0);
    gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, t.stats.get(), 0);
    const GLenum buffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    gl.DrawBuffers(2, buffers);
    if (gl.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        throw GlError("GL backend: float render targets of " + std::to_string(width) + "x" + std::to_string(height) +
                      " are not supported by this context");
    }
    return t;
}

std::vector<float> readAttachment(const glcontext::GlFunctions& gl, GLenum attachment, int width, int height) {
    std::vector<float> pixels(static_cast<size_t>(width) * static_cast<size_t>(height) * 4);
    gl.ReadBuffer(attachment);
    gl.PixelStorei(GL_PACK_ALIGNMENT, 4);
    gl.ReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, pixels.data());
    return pixels;
}

}  // namespace

GlRenderer::GlRenderer(const glcontext::GlFunctions& gl)
    : gl_(gl),
      paramBuffer_(glcontext::makeBuffer(gl)),
      paramTexture_(glcontext::makeTexture(gl)),
      vertexArray_(glcontext::makeVertexArray(gl)) {}

GlRenderer::~GlRenderer() = default;

const GlRenderer::CachedProgram& GlRenderer::programFor(const program::Program& program) {
    std::uint64_t key = program.structureKey();
    auto it = cache_.find(key);
    if (it != cache_.end()) {
        ++counters_.cacheHits;
        return *it->second;
    }
    if (worstCaseBackEdges(program) >= kLoopLimiter) {
        throw GlError("GL backend: one pass could take " + std::to_string(worstCaseBackEdges(program)) +
                      " loop iterations, over llvmpipe's limit of " + std::to_string(kLoopLimiter) +
                      "; lower render.max_steps or render.shadow_steps");
    }
    auto start = std::chrono::steady_clock::now();
    std::string fragment = generateFragmentShader(program);
    ++counters_.generations;
    const glcontext::ShaderSource stages[] = {{GL_VERTEX_SHADER, vertexShaderSource()},
                                              {GL_FRAGMENT_SHADER, fragment}};
    glcontext::ProgramBuild build = glcontext::buildProgram(gl_, stages, "scene");
    if (!build.ok()) {
        throw GlError("GL backend: the generated shader does not build (dump it with --dump-shader):\n" + build.report);
    }
    ++counters_.compiles;
    auto cached = std::make_unique<CachedProgram>();
    cached->program = std::move(build.program);
    for (const char* name : kUniformNames) {
        cached->uniforms[name] = gl_.GetUniformLocation(cached->program.get(), name);
    }
    counters_.lastCompileSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return *cache_.emplace(key, std::move(cached)).first->second;
}

void GlRenderer::prepare(const program::Program& program) { programFor(program); }

void GlRenderer::uploadParameters(const program::Program& program, const CachedProgram& cached) {
    std::vector<float> params;
    params.reserve(program.params.size() * 4 + 4);
    for (const glm::dvec4& v : program.params) {
        for (int i = 0; i < 4; ++i) params.push_back(static_cast<float>(v[i]));
    }
    if (params.empty()) params.assign(4, 0.0f);  // a buffer texture may not be empty
    gl_.BindBuffer(GL_TEXTURE_BUFFER, paramBuffer_.get());
    gl_.BufferData(GL_TEXTURE_BUFFER, static_cast<GLsizeiptr>(params.size() * sizeof(float)), params.data(),
                   GL_DYNAMIC_DRAW);
    gl_.BindBuffer(GL_TEXTURE_BUFFER, 0);
    gl_.ActiveTexture(GL_TEXTURE0);
    gl_.BindTexture(GL_TEXTURE_BUFFER, paramTexture_.get());
    gl_.TexBuffer(GL_TEXTURE_BUFFER, GL_RGBA32F, paramBuffer_.get());

    GLuint p = cached.program.get();
    gl_.UseProgram(p);
    auto vec3 = [&](const char* name, const glm::dvec3& v) {
        gl_.Uniform3f(cached.uniform(name), static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z));
    };
    gl_.Uniform1i(cached.uniform("uParams"), 0);
    vec3("uCameraOrigin", program.camera.origin);
    vec3("uCameraForward", program.camera.forward);
    vec3("uCameraRight", program.camera.right);
    vec3("uCameraUp", program.camera.up);
    gl_.Uniform1f(cached.uniform("uTanHalfFov"), static_cast<float>(program.camera.tanHalfFov));
    gl_.Uniform2f(cached.uniform("uResolution"), static_cast<float>(program.width), static_cast<float>(program.height));
    gl_.Uniform1i(cached.uniform("uAA"), program.aa);
    const program::TraceParams& t = program.trace;
    gl_.Uniform1i(cached.uniform("uMaxSteps"), t.maxSteps);
    gl_.Uniform1f(cached.uniform("uMaxDistance"), static_cast<float>(t.maxDistance));
    gl_.Uniform1f(cached.uniform("uEpsilon"), static_cast<float>(t.epsilon));
    gl_.Uniform1f(cached.uniform("uEpsilonPerDistance"), static_cast<float>(t.epsilonPerDistance));
    gl_.Uniform1i(cached.uniform("uShadowMode"), t.shadowMode);
    gl_.Uniform1i(cached.uniform("uShadowSteps"), t.shadowSteps);
    gl_.Uniform1i(cached.uniform("uAoSamples"), t.aoSamples);
    gl_.Uniform1f(cached.uniform("uAoDistance"), static_cast<float>(t.aoDistance));
    gl_.Uniform1i(cached.uniform("uLightingModel"), t.lightingModel);
    gl_.Uniform1i(cached.uniform("uLightCount"), static_cast<int>(program.lights.size()));
    vec3("uAmbientLight", t.ambientLight);
    vec3("uBackground", t.background);
    std::vector<float> directions(24, 0.0f), colors(24, 0.0f), softness(8, 1.0f);
    for (size_t i = 0; i < program.lights.size() && i < 8; ++i) {
        for (int c = 0; c < 3; ++c) {
            directions[3 * i + static_cast<size_t>(c)] = static_cast<float>(program.lights[i].direction[c]);
            colors[3 * i + static_cast<size_t>(c)] = static_cast<float>(program.lights[i].color[c]);
        }
        softness[i] = static_cast<float>(program.lights[i].softness);
    }
    gl_.Uniform3fv(cached.uniform("uLightDirection"), 8, directions.data());
    gl_.Uniform3fv(cached.uniform("uLightColor"), 8, colors.data());
    gl_.Uniform1fv(cached.uniform("uLightSoftness"), 8, softness.data());
}

GlRenderOutcome GlRenderer::render(const program::Program& program, const GlRenderControl& control) {
    const CachedProgram& cached = programFor(program);
    uploadParameters(program, cached);
    const int width = program.width, height = program.height, aa = program.aa;
    Targets targets = makeTargets(gl_, width, height);

    const float zero[4] = {0, 0, 0, 0};
    gl_.ClearBufferfv(GL_COLOR, 0, zero);
    gl_.ClearBufferfv(GL_COLOR, 1, zero);
    gl_.Viewport(0, 0, width, height);
    gl_.Enable(GL_SCISSOR_TEST);
    // Sub-sample passes add up in float, in the same order as the CPU backend's loop.
    gl_.Enable(GL_BLEND);
    gl_.BlendEquation(GL_FUNC_ADD);
    gl_.BlendFunc(GL_ONE, GL_ONE);
    gl_.BindVertexArray(vertexArray_.get());

    const int tile = std::max(16, control.tileSize);
    const int tilesX = (width + tile - 1) / tile, tilesY = (height + tile - 1) / tile;
    const int drawsTotal = tilesX * tilesY * aa * aa;
    int drawsDone = 0;
    GlRenderOutcome outcome;
    for (int ty = 0; ty < tilesY && !outcome.cancelled; ++ty) {
        for (int tx = 0; tx < tilesX && !outcome.cancelled; ++tx) {
            gl_.Scissor(tx * tile, ty * tile, tile, tile);
            for (int m = 0; m < aa && !outcome.cancelled; ++m) {
                for (int n = 0; n < aa; ++n) {
                    if (control.cancel && control.cancel->load()) {
                        outcome.cancelled = true;
                        break;
                    }
                    gl_.Uniform2i(cached.uniform("uSubsample"), m, n);
                    gl_.DrawArrays(GL_TRIANGLES, 0, 3);
                    // one draw at a time: a long queue would make cancel and progress lag
                    gl_.Finish();
                    if (control.progress) control.progress(++drawsDone, drawsTotal);
                }
            }
        }
    }
    gl_.Disable(GL_BLEND);
    gl_.Disable(GL_SCISSOR_TEST);
    gl_.BindVertexArray(0);

    if (!outcome.cancelled) {
        std::vector<float> color = readAttachment(gl_, GL_COLOR_ATTACHMENT0, width, height);
        std::vector<float> stats = readAttachment(gl_, GL_COLOR_ATTACHMENT1, width, height);
        image::Frame& frame = outcome.frame;
        frame.color = image::Image(width, height);
        frame.steps.assign(frame.color.pixelCount(), 0.0f);
        frame.coverage.assign(frame.color.pixelCount(), 0.0f);
        const float samples = static_cast<float>(aa * aa);
        for (int y = 0; y < height; ++y) {
            // GL rows start at the bottom; frames start at the top
            size_t source = static_cast<size_t>(height - 1 - y) * static_cast<size_t>(width);
            size_t target = static_cast<size_t>(y) * static_cast<size_t>(width);
            for (int x = 0; x < width; ++x) {
                size_t s = (source + static_cast<size_t>(x)) * 4, t = target + static_cast<size_t>(x);
                for (int c = 0; c < 3; ++c) frame.color.rgb[3 * t + static_cast<size_t>(c)] = color[s + static_cast<size_t>(c)] / samples;
                frame.steps[t] = stats[s] / samples;
                frame.coverage[t] = stats[s + 1] / samples;
            }
        }
    }
    gl_.BindFramebuffer(GL_FRAMEBUFFER, 0);
    gl_.UseProgram(0);
    glcontext::checkGlError(gl_, "GlRenderer::render");
    return outcome;
}

}  // namespace sdfwb::gl
