#pragma once
// Every scene file shipped in scenes/, for tests that run over all of them.

#include <algorithm>
#include <filesystem>
#include <vector>

namespace sdfwb::test {

inline std::vector<std::filesystem::path> allSceneFiles() {
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(SDFWB_SOURCE_DIR "/scenes")) {
        if (entry.is_regular_file() && entry.path().extension() == ".json") {
            files.push_back(entry.path());
        }
    }
    std::sort(files.begin(), files.end());
    return files;
}

}  // namespace sdfwb::test
