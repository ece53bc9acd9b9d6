#include "gl/progressive_render.h"

#include <algorithm>
#include <chrono>
#include <optional>

#include "glcontext/gl_debug.h"

namespace sdfwb::gl {

GlProgressiveRender::GlProgressiveRender(GlRenderer& renderer, program::Program program,
                                         const render::RenderControl& control, int defaultTileSize)
    : renderer_(renderer),
      gl_(renderer.functions()),
      program_(std::move(program)),
      targets_(makeRenderTargets(gl_, program_.width, program_.height)),
      tiles_(render::tilesToRender(program_.width, program_.height, control.region,
                                   std::max(kMinTileSize, control.tileSize > 0 ? control.tileSize : defaultTileSize))),
      frame_(render::blankFrame(program_.width, program_.height)),
      timer_(glcontext::makeQuery(gl_)) {
    const float zero[4] = {0, 0, 0, 0};
    gl_.ClearBufferfv(GL_COLOR, 0, zero);
    gl_.ClearBufferfv(GL_COLOR, 1, zero);
    gl_.BindFramebuffer(GL_FRAMEBUFFER, 0);
}

int GlProgressiveRender::drawsDone() const { return static_cast<int>(next_) * program_.aa * program_.aa + subsample_; }

int GlProgressiveRender::drawsTotal() const { return static_cast<int>(tiles_.size()) * program_.aa * program_.aa; }

double GlProgressiveRender::progress() const {
    if (tiles_.empty()) return 1.0;
    return static_cast<double>(drawsDone()) / static_cast<double>(drawsTotal());
}

std::vector<render::TileRect> GlProgressiveRender::advance(double budgetSeconds) {
    using Clock = std::chrono::steady_clock;
    const Clock::time_point start = Clock::now();
    std::optional<Clock::time_point> lastAsked;
    // A draw started just before the budget ran out used to overrun it by up
    // to a whole draw, and the viewport's frames by as much (36 ms for a 25 ms
    // budget on the molecule): the next draw is taken to last as long as the last.
    return draw([&] {
        const Clock::time_point now = Clock::now();
        bool another =
            !lastAsked || std::chrono::duration<double>(now - start + (now - *lastAsked)).count() <= budgetSeconds;
        lastAsked = now;
        return another;
    });
}

std::vector<render::TileRect> GlProgressiveRender::draw(const std::function<bool()>& another,
                                                        const std::function<void(int, int)>& afterEach) {
    std::vector<render::TileRect> finished;
    if (done() || !another()) return finished;
    const auto start = std::chrono::steady_clock::now();
    const int aa = program_.aa;
    // Errors still pending were raised by earlier calls of whoever shares the
    // context (the GUI's, which its KHR_debug log names); this draw fails
    // only for its own.
    glcontext::takeGlErrors(gl_);
    renderer_.bindForDrawing(program_);
    gl_.BindFramebuffer(GL_FRAMEBUFFER, targets_.framebuffer.get());
    gl_.Viewport(0, 0, program_.width, program_.height);
    renderer_.setDrawState(true);
    do {
        const render::TileRect& tile = tiles_[next_];
        gl_.Scissor(tile.x, program_.height - (tile.y + tile.h), tile.w, tile.h);
        gl_.BeginQuery(GL_TIME_ELAPSED, timer_.get());
        renderer_.drawSubsample(subsample_ / aa, subsample_ % aa);
        gl_.EndQuery(GL_TIME_ELAPSED);
        // Wait for this draw only: budgets, cancel and progress are about finished work.
        GLsync fence = gl_.FenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
        gl_.ClientWaitSync(fence, GL_SYNC_FLUSH_COMMANDS_BIT, 10'000'000'000ull);
        gl_.DeleteSync(fence);
        GLuint64 nanoseconds = 0;
        gl_.GetQueryObjectui64v(timer_.get(), GL_QUERY_RESULT, &nanoseconds);
        gpuSeconds_ += static_cast<double>(nanoseconds) * 1e-9;
        if (++subsample_ == aa * aa) {
            readFrameRegion(gl_, targets_, tile.x, tile.y, tile.w, tile.h, aa * aa, frame_);
            finished.push_back(tile);
            subsample_ = 0;
            ++next_;
        }
        if (afterEach) afterEach(drawsDone(), drawsTotal());
    } while (!done() && another());
    drawSeconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    renderer_.setDrawState(false);
    gl_.BindFramebuffer(GL_FRAMEBUFFER, 0);
    gl_.UseProgram(0);
    glcontext::checkGlError(gl_, "GlProgressiveRender::draw");
    return finished;
}

}  // namespace sdfwb::gl
