#include "cli_process.h"

#include <array>
#include <cstdio>
#include <cstdlib>
#include <memory>

#include <fcntl.h>
#include <sys/inotify.h>
#include <sys/wait.h>
#include <unistd.h>

namespace sdfwb::test {
namespace fs = std::filesystem;

namespace {

int statusOf(int status) { return WIFSIGNALED(status) ? 128 + WTERMSIG(status) : WEXITSTATUS(status); }

}  // namespace

ProcessResult run(const std::string& arguments, const std::string& prefix) {
    return runProgram(SDFWB_EXECUTABLE, arguments, prefix);
}

ProcessResult runProgram(const std::string& program, const std::string& arguments, const std::string& prefix) {
    std::string command = prefix + " " + program + " " + arguments + " 2>&1";
    std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
    std::string output;
    std::array<char, 4096> buffer{};
    size_t n = 0;
    while ((n = fread(buffer.data(), 1, buffer.size(), pipe.get())) > 0) output.append(buffer.data(), n);
    int status = pclose(pipe.release());
    // the shell reports a signal as its own exit status 128 + signal
    return {statusOf(status), output};
}

pid_t start(const std::vector<std::string>& arguments) {
    std::vector<char*> argv;
    std::string executable = SDFWB_EXECUTABLE;
    argv.push_back(executable.data());
    std::vector<std::string> copies = arguments;
    for (std::string& a : copies) argv.push_back(a.data());
    argv.push_back(nullptr);
    pid_t pid = fork();
    if (pid == 0) {
        int null = ::open("/dev/null", O_WRONLY);
        ::dup2(null, 1);
        ::dup2(null, 2);
        ::execv(executable.c_str(), argv.data());
        ::_exit(127);
    }
    return pid;
}

int waitFor(pid_t pid) {
    int status = 0;
    ::waitpid(pid, &status, 0);
    return statusOf(status);
}

std::string waitForFileCreated(const fs::path& folder, const std::string& part) {
    int fd = inotify_init1(IN_CLOEXEC);
    int watch = inotify_add_watch(fd, folder.c_str(), IN_CREATE);
    EXPECT_GE(watch, 0);
    alignas(inotify_event) char buffer[4096];
    while (true) {
        ssize_t n = ::read(fd, buffer, sizeof buffer);
        if (n <= 0) break;
        for (char* p = buffer; p < buffer + n;) {
            auto* event = reinterpret_cast<inotify_event*>(p);
            std::string name = event->len ? event->name : "";
            if (name.find(part) != std::string::npos) {
                ::close(fd);
                return name;
            }
            p += sizeof(inotify_event) + event->len;
        }
    }
    ::close(fd);
    return "";
}

void Cli::SetUp() {
    folder_ = fs::temp_directory_path() / ("sdfwb_cli_" + std::to_string(::getpid()) + "_" +
                                           ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(folder_);
    setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);
}

void Cli::TearDown() { fs::remove_all(folder_); }

std::size_t Cli::filesInFolder() const {
    return static_cast<std::size_t>(std::distance(fs::directory_iterator(folder_), {}));
}

}  // namespace sdfwb::test
