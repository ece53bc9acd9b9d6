#pragma once
// Every scene file shipped in scenes/, for tests that run over all of them.

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>
#include "support/source_tree.h"

namespace sdfwb::test {

// A scene file named by its path under scenes/ (what test names and messages show).
struct SceneFile {
    std::string relative;  // e.g. "hard/thin_blade.json"

    std::filesystem::path path() const {
        return std::filesystem::path(sdfwb::test::sourceDir() + "/scenes") / relative;
    }
    // scenes/hard/intended/ holds the intended results of hard cases (parity::intendedSceneFile), ordinary scenes
    bool isHardCase() const { return relative.rfind("hard/", 0) == 0 && relative.rfind("hard/intended/", 0) != 0; }
    // A gtest-safe name: "hard_thin_blade".
    std::string testName() const {
        std::string name = relative.substr(0, relative.size() - 5);
        for (char& c : name) {
            if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
        }
        return name;
    }
};

inline void PrintTo(const SceneFile& file, std::ostream* out) { *out << file.relative; }

inline std::vector<SceneFile> allSceneFiles() {
    const std::filesystem::path root = sdfwb::test::sourceDir() + "/scenes";
    std::vector<SceneFile> files;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(root)) {
        if (entry.is_regular_file() && entry.path().extension() == ".json") {
            files.push_back({std::filesystem::relative(entry.path(), root).string()});
        }
    }
    std::sort(files.begin(), files.end(), [](const SceneFile& a, const SceneFile& b) { return a.relative < b.relative; });
    return files;
}

}  // namespace sdfwb::test
