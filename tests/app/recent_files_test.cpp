// The recent-files list (issue 13, item 10): a file that no longer exists
// leaves the list.

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "app/user_files/recent_files.h"
#include "support/source_tree.h"

namespace sdfwb::app {
namespace {

TEST(RecentFiles, MissingFilesLeaveTheList) {
    std::filesystem::path home = std::filesystem::path(sdfwb::test::outputDir()) / "recent_files_test";
    std::filesystem::remove_all(home);
    std::filesystem::create_directories(home);
    setenv("XDG_CONFIG_HOME", home.c_str(), 1);
    std::filesystem::path kept = home / "kept.json", gone = home / "gone.json";
    std::ofstream(kept) << "{}";
    std::ofstream(gone) << "{}";
    RecentFiles recent;
    recent.remember(kept.string());
    recent.remember(gone.string());
    EXPECT_EQ(recent.entries().size(), 2u);
    EXPECT_EQ(RecentFiles().entries().size(), 2u) << "kept in the user's configuration";
    std::filesystem::remove(gone);
    EXPECT_EQ(recent.entries().size(), 2u) << "read on refresh, not on every call";
    recent.refresh();
    EXPECT_EQ(recent.entries(), std::vector<std::string>{kept.string()});
    unsetenv("XDG_CONFIG_HOME");
}

}  // namespace
}  // namespace sdfwb::app
