#pragma once
// The viewport's pixel readout (distance, steps, node under the cursor) off
// the UI thread: a pick needs the scene compiled (the prune grid can take
// seconds on a large scene), so requests go to a worker that compiles once
// per scene state and view size and reuses that program for every further
// pixel. A newer request supersedes one still queued; the UI shows the newest
// finished reading when it is ready and never waits.

#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include "cpu/pick.h"
#include "jobs/job_queue.h"
#include "scene/scene.h"

namespace sdfwb::ui {

// One answered request: which pixel of which scene state it is about.
struct PixelReading {
    std::uint64_t revision = 0;
    int width = 0, height = 0;
    double x = 0, y = 0;
    cpu::PickResult pick;
};

// The programs picks run on, one per scene state and view size, shared by
// the probes of one view (the readout's and the click's) so that a state is
// compiled once.
class PickPrograms {
public:
    // The program of `scene` in state `revision` at width x height, compiled
    // when it is not the one held (on the calling worker thread).
    std::shared_ptr<const program::Program> get(const scene::Scene& scene, std::uint64_t revision, int width,
                                                int height);
    int compiles() const;

private:
    mutable std::mutex mutex_;
    std::uint64_t revision_ = 0;
    int width_ = 0, height_ = 0;
    std::shared_ptr<const program::Program> program_;
    int compiles_ = 0;
};

class PixelProbe {
public:
    explicit PixelProbe(std::shared_ptr<PickPrograms> programs = std::make_shared<PickPrograms>())
        : programs_(std::move(programs)) {}
    PixelProbe(const PixelProbe&) = delete;
    PixelProbe& operator=(const PixelProbe&) = delete;

    // Asks for the pick of image point (x, y) of a width x height view of
    // `scene` in state `revision` (the editor's revision). Copies the scene
    // only when the revision is new; the same request again does nothing.
    void request(const scene::Scene& scene, std::uint64_t revision, int width, int height, double x, double y);
    // The newest finished reading (nullopt before the first); never waits.
    std::optional<PixelReading> latest() const;
    // The last request's reading is not finished yet.
    bool pending() const;
    // Waits for the last request (tests; the UI polls).
    void wait() const;
    const std::shared_ptr<PickPrograms>& programs() const { return programs_; }

private:
    struct Requested {
        std::uint64_t revision = 0;
        int width = 0, height = 0;
        double x = 0, y = 0;
        friend bool operator==(const Requested&, const Requested&) = default;
    };
    // The newest reading, written by the worker.
    struct Shared {
        mutable std::mutex mutex;
        std::optional<PixelReading> latest;
    };
    std::shared_ptr<PickPrograms> programs_;
    std::optional<Requested> requested_;
    std::shared_ptr<const scene::Scene> scene_;  // the state `requested_->revision` names
    std::shared_ptr<Shared> shared_ = std::make_shared<Shared>();
    jobs::JobHandle job_;
    jobs::JobQueue queue_{1};  // last: stops before the rest goes
};

// The readout's line for a reading: "steps 41   distance 0.0003 at (x, y, z)   root.children[0]".
std::string readoutText(const cpu::PickResult& pick);

}  // namespace sdfwb::ui
