#pragma once
// A fresh folder under the system's temporary directory, removed with its contents when the object goes.
// mkdtemp names it uniquely: CTest runs a file's tests in parallel processes, and two checkouts' suites
// may run on one machine at once; a folder named after the test alone was shared between them.

#include <stdlib.h>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <system_error>

namespace sdfwb::test {

class ScratchFolder {
public:
    explicit ScratchFolder(const std::string& prefix = "sdfwb_") {
        std::string pattern = (std::filesystem::temp_directory_path() / (prefix + "XXXXXX")).string();
        if (::mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("cannot make a folder like " + pattern);
        path_ = pattern;
    }
    ~ScratchFolder() {
        std::error_code ignored;
        std::filesystem::remove_all(path_, ignored);
    }
    ScratchFolder(const ScratchFolder&) = delete;
    ScratchFolder& operator=(const ScratchFolder&) = delete;

    const std::filesystem::path& path() const { return path_; }
    std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

private:
    std::filesystem::path path_;
};

}  // namespace sdfwb::test
