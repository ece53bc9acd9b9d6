#pragma once
// Writing files so that a failure or a cancel never leaves a partial file:
// write to a temporary sibling that keeps the real extension (OpenImageIO picks
// the writer from it), then rename it over the destination.

#include <filesystem>
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace sdfwb::io {

// "dir/name.tmp-<pid>-<n>.ext" next to `destination`.
std::filesystem::path temporarySibling(const std::filesystem::path& destination);

// Calls write(temporaryPath); if it returns normally and the file it wrote is
// complete (not empty, flushed to the disk), renames the temporary file over
// the destination. A destination that is a symbolic link is written through
// (the link's target is replaced, the link stays); an existing destination
// keeps its permissions. On any exception, and on a termination signal
// (temporary_files.h), the temporary file is removed and the previous file is
// left as it was. Throws std::runtime_error "cannot write <destination>: ...".
void writeAtomically(const std::filesystem::path& destination,
                     const std::function<void(const std::filesystem::path&)>& write);

// Several files that change together or not at all (an image and its heat
// map): each is written to its temporary file by stage(); commit() renames
// them all. Temporaries not committed are removed when the object dies.
class StagedWrites {
public:
    StagedWrites();
    ~StagedWrites();
    StagedWrites(const StagedWrites&) = delete;
    StagedWrites& operator=(const StagedWrites&) = delete;

    // Like writeAtomically up to the rename; throws on failure.
    void stage(const std::filesystem::path& destination,
               const std::function<void(const std::filesystem::path&)>& write);
    void commit();

private:
    struct Staged;
    std::vector<std::unique_ptr<Staged>> staged_;
};

// Writes `content` to `temporary` and checks that all of it arrived; throws
// std::runtime_error "cannot write <destination>: ..." (for write callbacks).
void writeContent(const std::filesystem::path& temporary, const std::filesystem::path& destination,
                  std::string_view content);

// Writes `content` atomically; throws std::runtime_error naming the path on failure.
void writeTextAtomically(const std::filesystem::path& destination, std::string_view content);

// Throws std::runtime_error "cannot write <path>: <reason>" when the file's
// folder does not exist or is not writable, or the path is a folder, so a long
// job can fail before it starts.
void checkCanCreate(const std::filesystem::path& destination);

// Throws std::runtime_error "cannot read <path>: <reason>", also when the file
// is larger than maxBytes.
std::string readTextFile(const std::filesystem::path& path, std::size_t maxBytes = std::size_t(1) << 30);

}  // namespace sdfwb::io
