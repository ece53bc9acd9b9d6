// The built-in file browser's folder listing (app/user_files/folder_listing.h): subfolders and the
// wanted kinds of file, sorted, extensions matched ignoring case, a bound on
// how many entries a folder may list, and a clear answer for a folder that
// cannot be read.

#include <fstream>

#include <gtest/gtest.h>

#include "app/user_files/folder_listing.h"
#include "support/scratch_folder.h"

namespace sdfwb::app {
namespace {

void touch(const std::filesystem::path& path) { std::ofstream(path) << "x"; }

TEST(FolderListing, ListsSubfoldersAndTheWantedFilesSortedByName) {
    test::ScratchFolder folder;
    std::filesystem::create_directories(folder / "b_textures");
    std::filesystem::create_directories(folder / "a_skies");
    for (const char* name : {"wood.PNG", "sky.exr", "notes.txt", "scene.json", "brick.jpg"}) touch(folder / name);
    ui::FolderListing listing = listFolder(folder.path(), {".png", ".jpg", ".exr"});
    ASSERT_EQ(listing.folders.size(), 2u);
    EXPECT_EQ(listing.folders[0].filename(), "a_skies");
    EXPECT_EQ(listing.folders[1].filename(), "b_textures");
    ASSERT_EQ(listing.files.size(), 3u);
    EXPECT_EQ(listing.files[0].filename(), "brick.jpg");
    EXPECT_EQ(listing.files[1].filename(), "sky.exr");
    EXPECT_EQ(listing.files[2].filename(), "wood.PNG");
    EXPECT_EQ(listing.omitted, 0u);
    EXPECT_TRUE(listing.error.empty());
}

TEST(FolderListing, AHugeFolderListsAtMostTheBoundAndCountsTheRest) {
    test::ScratchFolder folder;
    for (std::size_t i = 0; i < ui::kMaxListedEntries + 7; ++i) touch(folder / (std::to_string(i) + ".png"));
    ui::FolderListing listing = listFolder(folder.path(), {".png"});
    EXPECT_EQ(listing.files.size(), ui::kMaxListedEntries);
    EXPECT_EQ(listing.omitted, 7u);
}

TEST(FolderListing, AFolderThatCannotBeReadSaysSoAndListsNothing) {
    ui::FolderListing listing = listFolder("/nonexistent-folder/deeper", {".png"});
    EXPECT_TRUE(listing.folders.empty());
    EXPECT_TRUE(listing.files.empty());
    EXPECT_EQ(listing.error.rfind("cannot list /nonexistent-folder/deeper: ", 0), 0u) << listing.error;
}

}  // namespace
}  // namespace sdfwb::app
