#include "gl/gl_renderer.h"

#include <chrono>
#include <optional>
#include <vector>

#include "gl/fold_run.h"
#include "gl/program_size.h"
#include "gl/progressive_render.h"
#include "gl/shader_generator.h"
#include "glcontext/gl_debug.h"
#include "glcontext/shader_program.h"
#include "program/scene_images.h"
#include "sdf/shared.h"

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

const char* const kUniformNames[] = {"uParams",     "uResolution", "uSubsample", "uAA",
                                     "uPruneNodes", "uFoldSpans",  "uFoldBlocks", "uTexels"};
// Texture units: the parameters 0, the fold loop's lists 1 to 3, the scene images' texels 4.
constexpr int kTexelUnit = 4;
const char* const kFoldSamplers[] = {"uPruneNodes", "uFoldSpans", "uFoldBlocks"};

}  // namespace

GlRenderer::GlRenderer(const glcontext::GlFunctions& gl)
    : gl_(gl),
      paramBuffer_(glcontext::makeBuffer(gl)),
      paramTexture_(glcontext::makeTexture(gl)),
      vertexArray_(glcontext::makeVertexArray(gl)),
      texelBuffer_(glcontext::makeBuffer(gl)),
      texelTexture_(glcontext::makeTexture(gl)) {
    for (int i = 0; i < 3; ++i) {
        foldBuffers_[i] = glcontext::makeBuffer(gl);
        foldTextures_[i] = glcontext::makeTexture(gl);
    }
}

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
    // every build (the CLI's, the window's worker, thumbnails) refuses a
    // shader that would compile for minutes before generating it
    if (std::string problem = shaderSizeProblem(program); !problem.empty()) throw GlError("GL backend: " + problem);
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

void GlRenderer::warmUp(const program::Program& program) {
    program::Program tiny = program;
    tiny.width = tiny.height = 4;
    tiny.aa = 1;
    tiny.prune = false;  // the same shader; no grid built for four pixels
    render(tiny);
}

void GlRenderer::uploadParameters(const program::Program& program, const CachedProgram& cached) {
    std::vector<float> params;
    params.reserve(program.params.size() * 4 + 4);
    for (const glm::dvec4& v : program.params) {
        for (int i = 0; i < 4; ++i) params.push_back(static_cast<float>(v[i]));
    }
    // a fold loop reads the grid's extra slots and lists (its cell's kept blocks)
    std::optional<FoldRun> run = findFoldRun(program);
    std::shared_ptr<const prune::PruneGrid> grid;
    if (run && waitForGrid_) {
        grid = prune::pruneGridFor(program);
    } else if (run) {
        // until the grid is built, every block in every cell: the same floats, slower
        grid = prune::pruneGridIfBuilt(program).value_or(nullptr);
    }
    if (run) {
        std::vector<glm::dvec4> extra = grid ? grid->extraParams : prune::outsideBoundParams(program);
        if (!grid) {
            // one cell holding every block: (p - 0) * 0 lands in root cell 0 for every finite p
            extra.push_back(glm::dvec4(0.0));
            extra.push_back(glm::dvec4(1.0, 1.0, 1.0, 1.0));
        }
        for (const glm::dvec4& v : extra) {
            for (int i = 0; i < 4; ++i) params.push_back(static_cast<float>(v[i]));
        }
        FoldLists lists = foldLists(program, *run, grid.get());
        long perStep = 2 + (lists.longest + kFoldUnroll - 1) / kFoldUnroll;
        if (static_cast<long>(worstCaseBackEdges(program)) * perStep >= kLoopLimiter) {
            throw GlError("GL backend: one pass could take " +
                          std::to_string(static_cast<long>(worstCaseBackEdges(program)) * perStep) +
                          " loop iterations (a cell keeps " + std::to_string(lists.longest) +
                          " children), over llvmpipe's limit of " + std::to_string(kLoopLimiter) +
                          "; lower render.max_steps or render.shadow_steps, or use the CPU backend");
        }
        const std::vector<int>* data[3] = {&lists.nodes, &lists.spans, &lists.blocks};
        const GLenum formats[3] = {GL_R32I, GL_RG32I, GL_R32I};
        for (int t = 0; t < 3; ++t) {
            std::vector<int> values = data[t]->empty() ? std::vector<int>(2, 0) : *data[t];
            gl_.BindBuffer(GL_TEXTURE_BUFFER, foldBuffers_[t].get());
            gl_.BufferData(GL_TEXTURE_BUFFER, static_cast<GLsizeiptr>(values.size() * sizeof(int)), values.data(),
                           GL_DYNAMIC_DRAW);
            gl_.BindBuffer(GL_TEXTURE_BUFFER, 0);
            gl_.ActiveTexture(GL_TEXTURE1 + t);
            gl_.BindTexture(GL_TEXTURE_BUFFER, foldTextures_[t].get());
            gl_.TexBuffer(GL_TEXTURE_BUFFER, formats[t], foldBuffers_[t].get());
        }
    }
    program::ResolvedImages images = program::resolveImages(program);
    if (images.any()) {
        for (const auto& [slot, value] : images.slots) {
            for (int i = 0; i < 4; ++i) params[static_cast<size_t>(slot * 4 + i)] = static_cast<float>(value[i]);
        }
        uploadImages(images);
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
    gl_.Uniform1i(cached.uniform("uParams"), 0);
    for (int t = 0; t < 3; ++t) {
        if (run) gl_.Uniform1i(cached.uniform(kFoldSamplers[t]), 1 + t);
    }
    if (images.any()) gl_.Uniform1i(cached.uniform("uTexels"), kTexelUnit);
    gl_.Uniform2f(cached.uniform("uResolution"), static_cast<float>(program.width), static_cast<float>(program.height));
    gl_.Uniform1i(cached.uniform("uAA"), program.aa);
}

void GlRenderer::uploadImages(const program::ResolvedImages& images) {
    std::vector<std::shared_ptr<const image::MipmappedImages>> parts{images.environment};
    parts.insert(parts.end(), images.textures.begin(), images.textures.end());
    if (parts != uploadedImages_) {
        std::size_t count = 0;
        for (const auto& part : parts) count += part ? part->texels.size() : 0;
        GLint limit = 0;
        gl_.GetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &limit);
        if (count > static_cast<size_t>(limit)) {
            throw GlError("GL backend: the scene's images have " + std::to_string(count) +
                          " texels, over this driver's buffer texture limit of " + std::to_string(limit));
        }
        gl_.BindBuffer(GL_TEXTURE_BUFFER, texelBuffer_.get());
        gl_.BufferData(GL_TEXTURE_BUFFER, static_cast<GLsizeiptr>(count * sizeof(glm::vec4)), nullptr, GL_STATIC_DRAW);
        std::size_t offset = 0;
        for (const auto& part : parts) {
            if (!part) continue;
            gl_.BufferSubData(GL_TEXTURE_BUFFER, static_cast<GLintptr>(offset * sizeof(glm::vec4)),
                              static_cast<GLsizeiptr>(part->texels.size() * sizeof(glm::vec4)), part->texels.data());
            offset += part->texels.size();
        }
        gl_.BindBuffer(GL_TEXTURE_BUFFER, 0);
        uploadedImages_ = std::move(parts);
    }
    gl_.ActiveTexture(GL_TEXTURE0 + kTexelUnit);
    gl_.BindTexture(GL_TEXTURE_BUFFER, texelTexture_.get());
    gl_.TexBuffer(GL_TEXTURE_BUFFER, GL_RGBA32F, texelBuffer_.get());
}

bool GlRenderer::hasProgram(const program::Program& program) const {
    return cache_.contains(program.structureKey());
}

glcontext::GlObject GlRenderer::releaseProgram(const program::Program& program) {
    auto it = cache_.find(program.structureKey());
    if (it == cache_.end()) return {};
    if (bound_ == it->second.get()) bound_ = nullptr;
    glcontext::GlObject linked = std::move(it->second->program);
    cache_.erase(it);
    return linked;
}

void GlRenderer::adoptProgram(const program::Program& program, glcontext::GlObject linked) {
    auto cached = std::make_unique<CachedProgram>();
    cached->program = std::move(linked);
    for (const char* name : kUniformNames) {
        cached->uniforms[name] = gl_.GetUniformLocation(cached->program.get(), name);
    }
    auto& slot = cache_[program.structureKey()];
    if (bound_ == slot.get()) bound_ = nullptr;
    slot = std::move(cached);
}

void GlRenderer::bindForDrawing(const program::Program& program) {
    bound_ = &programFor(program);
    uploadParameters(program, *bound_);
    gl_.BindVertexArray(vertexArray_.get());
}

void GlRenderer::drawSubsample(int m, int n) {
    gl_.Uniform2i(bound_->uniform("uSubsample"), m, n);
    gl_.DrawArrays(GL_TRIANGLES, 0, 3);
}

void GlRenderer::setDrawState(bool on) {
    if (on) {
        gl_.Enable(GL_SCISSOR_TEST);
        // Sub-sample passes add up in float, in the same order as the CPU backend's loop.
        gl_.Enable(GL_BLEND);
        gl_.BlendEquation(GL_FUNC_ADD);
        gl_.BlendFunc(GL_ONE, GL_ONE);
    } else {
        gl_.Disable(GL_BLEND);
        gl_.Disable(GL_SCISSOR_TEST);
        gl_.BindVertexArray(0);
    }
}

render::RenderOutcome GlRenderer::render(const program::Program& program, const render::RenderControl& control) {
    GlProgressiveRender job(*this, program, control, kDefaultTileSize);
    render::RenderOutcome outcome;
    job.draw([&] { return !(outcome.cancelled = control.cancel && control.cancel->load()); }, control.progress);
    if (!outcome.cancelled) outcome.frame = job.frame();
    return outcome;
}

}  // namespace sdfwb::gl
