#include "io/atomic_file.h"

#include <atomic>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include <fcntl.h>
#include <unistd.h>

#include "io/temporary_files.h"

namespace sdfwb::io {
namespace {

std::runtime_error cannotWrite(const std::filesystem::path& destination, const std::string& reason) {
    return std::runtime_error("cannot write " + destination.string() + ": " + reason);
}

// The file a write to `destination` replaces: the target of a symbolic link
// (followed to the end of a chain), else the destination itself.
std::filesystem::path replacedFile(const std::filesystem::path& destination) {
    std::error_code error;
    if (!std::filesystem::is_symlink(destination, error)) {
        return destination;
    }
    std::filesystem::path target = std::filesystem::weakly_canonical(destination, error);
    if (error) {
        throw cannotWrite(destination, "cannot follow the symbolic link: " + error.message());
    }
    return target;
}

// Writers (libpng through OpenImageIO among them) can report success on a full
// disk; the bytes are only known to be there once fsync has succeeded.
void checkWritten(const std::filesystem::path& temporary, const std::filesystem::path& destination) {
    int fd = ::open(temporary.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) {
        throw cannotWrite(destination, std::string("the writer left no file: ") + std::strerror(errno));
    }
    bool synced = ::fsync(fd) == 0;
    int syncError = errno;
    ::close(fd);
    if (!synced) {
        throw cannotWrite(destination, std::strerror(syncError));
    }
    std::error_code error;
    if (std::filesystem::file_size(temporary, error) == 0 || error) {
        throw cannotWrite(destination, "the writer produced an empty file");
    }
}

}  // namespace

std::filesystem::path temporarySibling(const std::filesystem::path& destination) {
    static std::atomic<int> counter{0};
    std::filesystem::path result = destination;
    result.replace_filename(destination.stem().string() + ".tmp-" + std::to_string(::getpid()) + "-" +
                            std::to_string(counter++) + destination.extension().string());
    return result;
}

void checkCanCreate(const std::filesystem::path& destination) {
    std::filesystem::path file = replacedFile(destination);
    std::error_code error;
    if (std::filesystem::is_directory(file, error)) {
        throw cannotWrite(destination, "it is a folder");
    }
    std::filesystem::path folder = file.parent_path();
    if (folder.empty()) {
        folder = ".";
    }
    if (!std::filesystem::is_directory(folder, error)) {
        throw cannotWrite(destination, "folder " + folder.string() + " does not exist");
    }
    if (::access(folder.c_str(), W_OK) != 0) {
        throw cannotWrite(destination, std::strerror(errno));
    }
}

struct StagedWrites::Staged {
    std::filesystem::path destination;  // as given, for messages
    std::filesystem::path file;         // the file replaced (a link's target)
    std::filesystem::path temporary;
    TemporaryFile registration;
    bool done = false;                  // renamed or removed
};

StagedWrites::StagedWrites() = default;

StagedWrites::~StagedWrites() {
    for (const auto& s : staged_) {
        if (!s->done) {
            std::error_code ignored;
            std::filesystem::remove(s->temporary, ignored);
        }
    }
}

void StagedWrites::stage(const std::filesystem::path& destination,
                         const std::function<void(const std::filesystem::path&)>& write) {
    checkCanCreate(destination);
    const std::filesystem::path file = replacedFile(destination);
    removeStaleTemporaries(file);
    const std::filesystem::path temporary = temporarySibling(file);
    staged_.push_back(std::unique_ptr<Staged>(new Staged{destination, file, temporary, TemporaryFile(temporary)}));
    write(temporary);
    checkWritten(temporary, destination);
    std::error_code error;
    const std::filesystem::file_status previous = std::filesystem::status(file, error);
    if (!error && std::filesystem::exists(previous)) {
        std::filesystem::permissions(temporary, previous.permissions(), error);
    }
}

void StagedWrites::commit() {
    for (const auto& s : staged_) {
        std::error_code error;
        std::filesystem::rename(s->temporary, s->file, error);
        if (error) {
            throw cannotWrite(s->destination, error.message());
        }
        s->done = true;
    }
}

void writeAtomically(const std::filesystem::path& destination,
                     const std::function<void(const std::filesystem::path&)>& write) {
    StagedWrites writes;
    writes.stage(destination, write);
    writes.commit();
}

void writeContent(const std::filesystem::path& temporary, const std::filesystem::path& destination,
                  std::string_view content) {
    std::ofstream out(temporary, std::ios::binary);
    if (!out) {
        throw cannotWrite(destination, std::strerror(errno));
    }
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    out.close();
    if (!out) {
        throw cannotWrite(destination, "write failed (is the disk full?)");
    }
    std::error_code error;
    if (std::filesystem::file_size(temporary, error) != content.size() || error) {
        throw cannotWrite(destination, "the file is shorter than its content (is the disk full?)");
    }
}

void writeTextAtomically(const std::filesystem::path& destination, std::string_view content) {
    writeAtomically(destination,
                    [&](const std::filesystem::path& temporary) { writeContent(temporary, destination, content); });
}

std::string readTextFile(const std::filesystem::path& path, std::size_t maxBytes) {
    std::error_code error;
    if (std::filesystem::is_directory(path, error)) {
        throw std::runtime_error("cannot read " + path.string() + ": it is a folder");
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        throw std::runtime_error("cannot read " + path.string() + ": " + std::strerror(errno));
    }
    std::string content;
    char buffer[1 << 16];
    while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
        if (content.size() + static_cast<std::size_t>(in.gcount()) > maxBytes) {
            throw std::runtime_error("cannot read " + path.string() + ": larger than " + std::to_string(maxBytes) +
                                     " bytes");
        }
        content.append(buffer, static_cast<std::size_t>(in.gcount()));
    }
    if (in.bad()) {
        throw std::runtime_error("cannot read " + path.string() + ": read failed");
    }
    return content;
}

}  // namespace sdfwb::io
