#pragma once
// The CPU backend behind the backend contract (render/render_backend.h): the
// reference that always works. Needs no build step; its progressive renders
// run on the backend's job queue, tiles spread over oneTBB.

#include "jobs/job_queue.h"
#include "render/render_backend.h"

namespace sdfwb::cpu {

class CpuBackend : public render::Backend {
public:
    std::string name() const override { return "cpu"; }
    std::string device() const override { return "CPU"; }
    render::RenderOutcome render(const program::Program& program, const render::RenderControl& control) override;
    std::unique_ptr<render::ProgressiveRender> startProgressive(program::Program program,
                                                                const render::RenderControl& control) override;

private:
    jobs::JobQueue jobs_{1};  // progressive renders, one at a time, newest last
};

}  // namespace sdfwb::cpu
