// A scene save killed at any moment of its write (SIGKILL: nothing can catch
// it, nothing runs after it) leaves the previous file as it was: the save
// writes a temporary sibling and renames it only once it is complete. A child
// process runs the save's writer and kills itself with the temporary file
// empty, half written and whole; the next save removes what it left.

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>

#include "io/atomic_file.h"
#include "scene/scene_json.h"
#include "support/source_tree.h"

namespace sdfwb::scene {
namespace {

namespace fs = std::filesystem;

std::size_t filesIn(const fs::path& folder) {
    return static_cast<std::size_t>(std::distance(fs::directory_iterator(folder), fs::directory_iterator()));
}

TEST(SceneSave, AKillInTheMiddleOfTheWriteLeavesThePreviousFile) {
    const fs::path folder = fs::path(sdfwb::test::outputDir()) / "save_killed";
    fs::remove_all(folder);
    fs::create_directories(folder);
    const fs::path path = folder / "scene.json";
    const Scene original = loadSceneFile(fs::path(sdfwb::test::sourceDir()) / "scenes/default.json");
    saveSceneFile(original, path);
    const std::string before = io::readTextFile(path);
    Scene edited = original;
    edited.name = "edited";
    const std::string text = serializeScene(edited);

    for (double written : {0.0, 0.5, 1.0}) {
        SCOPED_TRACE(written);
        pid_t pid = ::fork();
        ASSERT_GE(pid, 0);
        if (pid == 0) {
            // the save's own steps up to the rename, killed inside them
            io::writeAtomically(path, [&](const fs::path& temporary) {
                io::writeContent(temporary, path, std::string_view(text).substr(0, text.size() * written));
                ::kill(::getpid(), SIGKILL);
            });
            ::_exit(0);  // not reached: the kill came first
        }
        int status = 0;
        ASSERT_EQ(::waitpid(pid, &status, 0), pid);
        ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL);
        EXPECT_EQ(io::readTextFile(path), before);
        EXPECT_EQ(loadSceneFile(path), original);
    }
    // each save first removes what killed ones left: the last one's is there
    EXPECT_EQ(filesIn(folder), 2u);
    saveSceneFile(edited, path);
    EXPECT_EQ(loadSceneFile(path), edited);
    EXPECT_EQ(filesIn(folder), 1u) << "the next save removes the temporaries of killed ones";
}

}  // namespace
}  // namespace sdfwb::scene
