// Atomic and staged writes, in a fresh folder per test: the destination is
// whole or as it was, permissions and symbolic links are kept, no temporary
// file stays behind, stale temporaries of dead writers are removed.

#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "io/atomic_file.h"
#include "io/temporary_files.h"
#include "support/source_tree.h"

namespace sdfwb::io {
namespace {

namespace fs = std::filesystem;

class AtomicFile : public ::testing::Test {
protected:
    void SetUp() override {
        const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
        folder_ = fs::path(sdfwb::test::outputDir()) / "io" / info->name();
        fs::remove_all(folder_);
        fs::create_directories(folder_);
    }

    fs::path folder_;

    static std::string contents(const fs::path& path) {
        std::ifstream in(path, std::ios::binary);
        std::stringstream text;
        text << in.rdbuf();
        return text.str();
    }

    // The folder's entries other than `keep`.
    int othersThan(const fs::path& keep) const {
        int count = 0;
        for (const fs::directory_entry& entry : fs::directory_iterator(folder_)) {
            if (entry.path().filename() != keep.filename()) ++count;
        }
        return count;
    }
};

TEST_F(AtomicFile, TemporarySiblingKeepsTheFolderAndTheExtension) {
    fs::path destination = folder_ / "image.png";
    fs::path a = temporarySibling(destination), b = temporarySibling(destination);
    EXPECT_EQ(a.parent_path(), folder_);
    EXPECT_EQ(a.extension(), ".png");
    EXPECT_EQ(a.filename().string().rfind("image.tmp-" + std::to_string(::getpid()) + "-", 0), 0u) << a;
    EXPECT_NE(a, b);
}

TEST_F(AtomicFile, WritesNewFilesAndReplacesOldOnes) {
    fs::path destination = folder_ / "scene.json";
    writeTextAtomically(destination, "first");
    EXPECT_EQ(contents(destination), "first");
    writeTextAtomically(destination, "second, longer");
    EXPECT_EQ(contents(destination), "second, longer");
    EXPECT_EQ(othersThan(destination), 0) << "no temporary left";
}

TEST_F(AtomicFile, AFailingWriteLeavesThePreviousFileAndNoTemporary) {
    fs::path destination = folder_ / "scene.json";
    writeTextAtomically(destination, "kept");
    EXPECT_THROW(writeAtomically(destination,
                                 [](const fs::path& temporary) {
                                     std::ofstream(temporary) << "half";
                                     throw std::runtime_error("cancelled");
                                 }),
                 std::runtime_error);
    EXPECT_EQ(contents(destination), "kept");
    EXPECT_EQ(othersThan(destination), 0);
}

TEST_F(AtomicFile, AnEmptyResultIsRefused) {
    fs::path destination = folder_ / "scene.json";
    writeTextAtomically(destination, "kept");
    try {
        writeAtomically(destination, [](const fs::path& temporary) { std::ofstream{temporary}; });
        FAIL() << "an empty file was accepted";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("cannot write " + destination.string()), std::string::npos) << e.what();
    }
    EXPECT_EQ(contents(destination), "kept");
    EXPECT_EQ(othersThan(destination), 0);
}

TEST_F(AtomicFile, PermissionsOfTheReplacedFileAreKept) {
    fs::path destination = folder_ / "private.json";
    writeTextAtomically(destination, "one");
    fs::permissions(destination, fs::perms::owner_read | fs::perms::owner_write);
    writeTextAtomically(destination, "two");
    EXPECT_EQ(fs::status(destination).permissions() & fs::perms::all, fs::perms::owner_read | fs::perms::owner_write);
}

TEST_F(AtomicFile, ASymbolicLinkIsWrittenThrough) {
    fs::path target = folder_ / "target.json", link = folder_ / "link.json";
    writeTextAtomically(target, "old");
    fs::create_symlink(target.filename(), link);
    writeTextAtomically(link, "new");
    EXPECT_TRUE(fs::is_symlink(link));
    EXPECT_EQ(contents(target), "new");
}

TEST_F(AtomicFile, StagedWritesAppearTogetherOnCommitOnly) {
    fs::path image = folder_ / "frame.png", heat = folder_ / "frame-heat.png";
    {
        StagedWrites writes;
        writes.stage(image, [&](const fs::path& t) { writeContent(t, image, "image"); });
        writes.stage(heat, [&](const fs::path& t) { writeContent(t, heat, "heat"); });
    }
    EXPECT_TRUE(fs::is_empty(folder_)) << "uncommitted writes leave nothing";
    StagedWrites writes;
    writes.stage(image, [&](const fs::path& t) { writeContent(t, image, "image"); });
    writes.stage(heat, [&](const fs::path& t) { writeContent(t, heat, "heat"); });
    writes.commit();
    EXPECT_EQ(contents(image), "image");
    EXPECT_EQ(contents(heat), "heat");
}

TEST_F(AtomicFile, CheckCanCreateRefusesFoldersAndMissingFolders) {
    EXPECT_NO_THROW(checkCanCreate(folder_ / "new.json"));
    EXPECT_THROW(checkCanCreate(folder_), std::runtime_error);
    try {
        checkCanCreate(folder_ / "missing" / "new.json");
        FAIL() << "a missing folder was accepted";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("missing"), std::string::npos) << e.what();
    }
}

TEST_F(AtomicFile, ReadTextFileReadsAndBoundsTheSize) {
    fs::path file = folder_ / "text.txt";
    writeTextAtomically(file, "0123456789");
    EXPECT_EQ(readTextFile(file), "0123456789");
    EXPECT_EQ(readTextFile(file, 10), "0123456789");
    EXPECT_THROW(readTextFile(file, 9), std::runtime_error);
    try {
        readTextFile(folder_ / "absent.txt");
        FAIL() << "a missing file was read";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("cannot read"), std::string::npos) << e.what();
    }
}

TEST_F(AtomicFile, StaleTemporariesOfDeadWritersAreRemoved) {
    // a process that has ended: its temporary is stale
    pid_t child = ::fork();
    if (child == 0) ::_exit(0);
    ASSERT_GT(child, 0);
    ::waitpid(child, nullptr, 0);
    fs::path destination = folder_ / "scene.json";
    fs::path stale = folder_ / ("scene.tmp-" + std::to_string(child) + "-0.json");
    fs::path live = folder_ / ("scene.tmp-" + std::to_string(::getpid()) + "-0.json");
    fs::path unrelated = folder_ / "scene.tmp-notes.json";
    for (const fs::path& p : {stale, live, unrelated}) std::ofstream(p) << "x";
    removeStaleTemporaries(destination);
    EXPECT_FALSE(fs::exists(stale));
    EXPECT_TRUE(fs::exists(live)) << "this process's own temporary";
    EXPECT_TRUE(fs::exists(unrelated)) << "not the temporary pattern";
}

}  // namespace
}  // namespace sdfwb::io
