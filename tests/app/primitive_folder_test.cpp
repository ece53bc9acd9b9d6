// The primitive library as a file-system service: listed once and after its
// own changes (not per frame), and a removed entry can be put back.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "app/user_files/primitive_folder.h"
#include "support/source_tree.h"

namespace sdfwb::app {
namespace {

std::filesystem::path freshFolder(const std::string& name) {
    std::filesystem::path folder = std::filesystem::path(sdfwb::test::outputDir()) / "primitive_library" / name;
    std::filesystem::remove_all(folder);
    return folder;
}

scene::Node ball() {
    scene::Node node = scene::Node::make(scene::NodeKind::Sphere);
    node.set("radius", 0.25);
    return node;
}

TEST(PrimitiveFolder, ListsOnceAndAfterItsOwnChanges) {
    std::filesystem::path folder = freshFolder("listing");
    PrimitiveFolder library(folder);
    EXPECT_TRUE(library.entries().empty());
    library.save("ball", ball());
    EXPECT_EQ(library.entries(), std::vector<std::string>{"ball"});
    // a file another program adds is seen after refresh(), not on every call
    std::ofstream(folder / "other.json") << "{\"kind\": \"sphere\"}\n";
    EXPECT_EQ(library.entries(), std::vector<std::string>{"ball"});
    library.refresh();
    EXPECT_EQ(library.entries(), (std::vector<std::string>{"ball", "other"}));
    EXPECT_DOUBLE_EQ(library.load("ball").real("radius"), 0.25);
}

TEST(PrimitiveFolder, ARemovedEntryCanBePutBack) {
    std::filesystem::path folder = freshFolder("remove");
    PrimitiveFolder library(folder);
    library.save("ball", ball());
    std::string before;
    {
        std::ifstream in(folder / "ball.json");
        before.assign(std::istreambuf_iterator<char>(in), {});
    }
    library.remove("ball");
    EXPECT_TRUE(library.entries().empty());
    EXPECT_FALSE(std::filesystem::exists(folder / "ball.json"));
    ASSERT_EQ(library.removed(), std::optional<std::string>("ball"));
    library.restoreRemoved();
    EXPECT_FALSE(library.removed());
    EXPECT_EQ(library.entries(), std::vector<std::string>{"ball"});
    std::ifstream in(folder / "ball.json");
    EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), before);
}

TEST(PrimitiveFolder, BadNamesAndMissingEntriesSayWhat) {
    PrimitiveFolder library(freshFolder("bad"));
    EXPECT_THROW(library.save("../escape", ball()), std::runtime_error);
    EXPECT_THROW(library.remove("missing"), std::runtime_error);
    EXPECT_FALSE(library.removed());
}

}  // namespace
}  // namespace sdfwb::app
