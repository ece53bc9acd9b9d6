#include "app/output_paths.h"

#include <filesystem>
#include <stdexcept>

#include "io/atomic_file.h"

namespace sdfwb::app {
namespace {

// Same file: the same resolved path (links followed, "." and ".." removed), or
// for existing files the same inode (a hard link).
bool sameFile(const std::string& a, const std::string& b) {
    std::error_code error;
    if (std::filesystem::equivalent(a, b, error) && !error) {
        return true;
    }
    std::filesystem::path ca = std::filesystem::weakly_canonical(std::filesystem::absolute(a), error);
    std::filesystem::path cb = std::filesystem::weakly_canonical(std::filesystem::absolute(b), error);
    return ca == cb;
}

}  // namespace

void checkOutputs(const std::vector<NamedPath>& inputs, const std::vector<NamedPath>& outputs) {
    for (std::size_t i = 0; i < outputs.size(); ++i) {
        const NamedPath& output = outputs[i];
        if (output.path.empty()) {
            continue;
        }
        auto clash = [&](const NamedPath& other) {
            if (!other.path.empty() && sameFile(output.path, other.path)) {
                throw std::invalid_argument(output.role + " " + output.path + " is the same file as " + other.role +
                                            " " + other.path + " (an output may not replace an input or "
                                                               "another output)");
            }
        };
        for (const NamedPath& input : inputs) clash(input);
        for (std::size_t j = 0; j < i; ++j) clash(outputs[j]);
        io::checkCanCreate(output.path);
    }
}

}  // namespace sdfwb::app
