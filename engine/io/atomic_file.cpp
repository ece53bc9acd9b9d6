#include "io/atomic_file.h"

#include <atomic>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include <unistd.h>

namespace sdfwb::io {

std::filesystem::path temporarySibling(const std::filesystem::path& destination) {
    static std::atomic<int> counter{0};
    std::filesystem::path result = destination;
    result.replace_filename(destination.stem().string() + ".tmp-" + std::to_string(::getpid()) + "-" +
                            std::to_string(counter++) + destination.extension().string());
    return result;
}

void checkCanCreate(const std::filesystem::path& destination) {
    std::filesystem::path folder = destination.parent_path();
    if (folder.empty()) {
        folder = ".";
    }
    std::error_code error;
    if (!std::filesystem::is_directory(folder, error)) {
        throw std::runtime_error("cannot write " + destination.string() + ": folder " + folder.string() +
                                 " does not exist");
    }
    if (::access(folder.c_str(), W_OK) != 0) {
        throw std::runtime_error("cannot write " + destination.string() + ": " + std::strerror(errno));
    }
}

void writeAtomically(const std::filesystem::path& destination,
                     const std::function<void(const std::filesystem::path&)>& write) {
    checkCanCreate(destination);
    std::filesystem::path temporary = temporarySibling(destination);
    try {
        write(temporary);
        std::error_code error;
        std::filesystem::rename(temporary, destination, error);
        if (error) {
            throw std::runtime_error("cannot write " + destination.string() + ": " + error.message());
        }
    } catch (...) {
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        throw;
    }
}

void writeTextAtomically(const std::filesystem::path& destination, std::string_view content) {
    writeAtomically(destination, [&](const std::filesystem::path& temporary) {
        std::ofstream out(temporary, std::ios::binary);
        if (!out) {
            throw std::runtime_error("cannot write " + destination.string() + ": " + std::strerror(errno));
        }
        out.write(content.data(), static_cast<std::streamsize>(content.size()));
        out.close();
        if (!out) {
            throw std::runtime_error("cannot write " + destination.string() + ": write failed");
        }
    });
}

std::string readTextFile(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        throw std::runtime_error("cannot read " + path.string() + ": " + std::strerror(errno));
    }
    std::ostringstream content;
    content << in.rdbuf();
    return content.str();
}

}  // namespace sdfwb::io
