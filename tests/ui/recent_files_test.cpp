// The recent-files list (issue 13, item 10): a file that no longer exists
// leaves the list.

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "support/source_tree.h"
#include "ui/user_paths.h"

namespace sdfwb::ui {
namespace {

TEST(RecentFiles, MissingFilesLeaveTheList) {
    std::filesystem::path home = std::filesystem::path(sdfwb::test::outputDir()) / "recent_files_test";
    std::filesystem::remove_all(home);
    std::filesystem::create_directories(home);
    setenv("XDG_CONFIG_HOME", home.c_str(), 1);
    std::filesystem::path kept = home / "kept.json", gone = home / "gone.json";
    std::ofstream(kept) << "{}";
    std::ofstream(gone) << "{}";
    rememberRecentFile(kept.string());
    rememberRecentFile(gone.string());
    EXPECT_EQ(loadRecentFiles().size(), 2u);
    std::filesystem::remove(gone);
    EXPECT_EQ(loadRecentFiles(), std::vector<std::string>{kept.string()});
    unsetenv("XDG_CONFIG_HOME");
}

}  // namespace
}  // namespace sdfwb::ui
