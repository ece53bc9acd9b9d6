#pragma once
// Writing files so that a failure or a cancel never leaves a partial file:
// write to a temporary sibling that keeps the real extension (OpenImageIO picks
// the writer from it), then rename it over the destination.

#include <filesystem>
#include <functional>
#include <string_view>

namespace sdfwb::io {

// "dir/name.tmp-<pid>-<n>.ext" next to `destination`.
std::filesystem::path temporarySibling(const std::filesystem::path& destination);

// Calls write(temporaryPath); if it returns normally, renames the temporary file
// to `destination`. On any exception the temporary file is removed and the
// exception propagates. Throws std::runtime_error naming `destination` when the
// rename fails.
void writeAtomically(const std::filesystem::path& destination,
                     const std::function<void(const std::filesystem::path&)>& write);

// Writes `content` atomically; throws std::runtime_error naming the path on failure.
void writeTextAtomically(const std::filesystem::path& destination, std::string_view content);

// Throws std::runtime_error "cannot write <path>: <reason>" when the file's
// folder does not exist or is not writable, so a long job can fail before it starts.
void checkCanCreate(const std::filesystem::path& destination);

// Throws std::runtime_error "cannot read <path>: <reason>".
std::string readTextFile(const std::filesystem::path& path);

}  // namespace sdfwb::io
