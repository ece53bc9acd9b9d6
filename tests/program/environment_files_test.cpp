// The environment map's files as the scene names them (program/scene_images.h):
// resolved against the scene's folder, only those the chosen map reads, a
// missing name reported by its key, and names rebased when the scene moves.

#include <gtest/gtest.h>

#include "program/scene_images.h"

namespace sdfwb::program {
namespace {

scene::Scene boxMapIn(const std::string& folder) {
    scene::Scene s;
    s.directory.path = folder;
    s.environment.map = scene::EnvironmentMapKind::Box;
    s.environment.image = "ignored.png";  // the box map reads its faces only
    s.environment.boxPositiveX = "faces/px.png";
    s.environment.boxNegativeX = "../shared/nx.png";
    s.environment.boxPositiveY = "/absolute/py.png";
    s.environment.boxNegativeY = "ny.png";
    s.environment.boxPositiveZ = "pz.png";
    s.environment.boxNegativeZ = "";
    return s;
}

TEST(EnvironmentFiles, AreTheChosenMapsResolvedAgainstTheScenesFolder) {
    std::vector<SceneImageFile> files = environmentFiles(boxMapIn("/scenes/tutorial"));
    ASSERT_EQ(files.size(), 6u);
    EXPECT_EQ(files[0].key, "environment.box_px");
    EXPECT_EQ(files[0].path, "/scenes/tutorial/faces/px.png");
    EXPECT_EQ(files[1].path, "/scenes/shared/nx.png");
    EXPECT_EQ(files[2].path, "/absolute/py.png");
    scene::Scene colour;
    colour.environment.image = "sky.png";
    EXPECT_TRUE(environmentFiles(colour).empty());
}

TEST(EnvironmentFiles, AFaceWithoutANameIsAProblemNamedByItsKey) {
    std::vector<std::string> problems = environmentProblems(boxMapIn("/nonexistent-folder"));
    ASSERT_EQ(problems.size(), 6u);  // five that cannot be read, one not given
    EXPECT_EQ(problems[5], "environment.box_nz: the box map needs an image file here");
    EXPECT_EQ(problems[0].rfind("environment.box_px: cannot read image /nonexistent-folder/faces/px.png", 0), 0u)
        << problems[0];
}

TEST(EnvironmentFiles, MovingTheSceneKeepsItsRelativeNamesPointingAtTheSameFiles) {
    scene::Scene s = boxMapIn("/scenes/tutorial");
    std::vector<SceneImageFile> before = environmentFiles(s);
    moveSceneDirectory(s, "/elsewhere/deep");
    EXPECT_EQ(s.directory.path, "/elsewhere/deep");
    EXPECT_EQ(s.environment.boxPositiveX, "../../scenes/tutorial/faces/px.png");
    EXPECT_EQ(s.environment.boxPositiveY, "/absolute/py.png");  // absolute names stay
    EXPECT_EQ(s.environment.boxNegativeZ, "");
    std::vector<SceneImageFile> after = environmentFiles(s);
    for (size_t i = 0; i < before.size(); ++i) {
        if (!before[i].name.empty()) EXPECT_EQ(after[i].path, before[i].path) << before[i].key;  // "" names no file
    }
}

}  // namespace
}  // namespace sdfwb::program
