#pragma once
// Checks of a command's output files before any work starts: each can be
// created, none is one of the command's inputs, and no two are the same file
// (a render's -o equal to its scene would overwrite the scene; --heat equal to
// -o would replace the image by the heat map).

#include <string>
#include <vector>

namespace sdfwb::app {

struct NamedPath {
    std::string role;  // how the user gave it: "-o", "--heat", "the scene"
    std::string path;  // "" = not given, skipped
};

// Throws std::invalid_argument "<role> <path> is the same file as <role> <path>"
// or std::runtime_error "cannot write <path>: ..." (io::checkCanCreate).
void checkOutputs(const std::vector<NamedPath>& inputs, const std::vector<NamedPath>& outputs);

}  // namespace sdfwb::app
