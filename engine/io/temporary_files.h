#pragma once
// Temporary files that must not outlive the process: the atomic writer
// registers each one while it exists, and a termination signal (SIGINT,
// SIGTERM, SIGHUP) removes them before the process ends with the signal's
// conventional status. Files left by a process killed with SIGKILL are found
// by their name (which holds the writer's process id) and removed by the next
// write to the same destination.

#include <filesystem>

namespace sdfwb::io {

// Installs the handlers: a termination signal removes the registered files and
// then ends the process as the signal's default action would (exit status
// 128 + signal number in a shell); exit() removes them too. Idempotent.
void removeTemporariesOnTermination();

// Registers `path` for removal on a termination signal while this object lives.
// At most a few dozen files are registered at once (more are not tracked).
class TemporaryFile {
public:
    explicit TemporaryFile(const std::filesystem::path& path);
    ~TemporaryFile();
    TemporaryFile(const TemporaryFile&) = delete;
    TemporaryFile& operator=(const TemporaryFile&) = delete;

private:
    int slot_ = -1;
};

// Removes temporary siblings of `destination` (temporarySibling's pattern)
// whose writing process no longer runs.
void removeStaleTemporaries(const std::filesystem::path& destination);

}  // namespace sdfwb::io
