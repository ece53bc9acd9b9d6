// The scene's image files as it names them (program/scene_images.h), the
// environment map's and the textures': resolved against the scene's folder,
// only those the chosen map and the image textures read, a missing name
// reported by its key, names rebased when the scene moves, each file read
// once and placed in the texel buffer after the environment's.

#include <algorithm>

#include <gtest/gtest.h>

#include "image/encoding.h"
#include "image/image_io.h"
#include "program/compile_scene.h"
#include "program/scene_images.h"
#include "scene/scene_json.h"
#include "scene/scene_validation.h"
#include "support/scratch_folder.h"

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
        if (!before[i].name.empty()) {  // "" names no file
            EXPECT_EQ(after[i].path, before[i].path) << before[i].key;
        }
    }
}

TEST(SceneFileNames, APickedFileIsNamedRelativeToTheScenesFolder) {
    scene::Scene s;
    s.directory.path = "/scenes/tutorial";
    for (const char* file : {"/scenes/tutorial/textures/wood.png", "/scenes/shared/sky.exr", "/elsewhere/a.png"}) {
        std::string name = sceneFileName(s, file);
        EXPECT_FALSE(std::filesystem::path(name).is_absolute()) << name;
        EXPECT_EQ(sceneFilePath(s, name), file) << name;
    }
    EXPECT_EQ(sceneFileName(s, "/scenes/tutorial/textures/../textures/wood.png"), "textures/wood.png");
    EXPECT_EQ(sceneFileName(s, "/scenes/shared/sky.exr"), "../shared/sky.exr");
}

scene::Scene texturedIn(const std::string& folder) {
    scene::Scene s;
    s.directory.path = folder;
    auto material = [&](const char* name, scene::TexturePattern pattern, const char* file) {
        scene::Material m;
        m.name = name;
        m.texture = pattern;
        m.textureImage = file;
        s.materials.push_back(m);
    };
    material("wood", scene::TexturePattern::Image, "textures/wood.png");
    material("checks", scene::TexturePattern::Checker, "ignored.png");  // a pattern reads no file
    material("unnamed", scene::TexturePattern::Image, "");
    material("oak", scene::TexturePattern::Image, "textures/wood.png");
    return s;
}

TEST(TextureFiles, AreTheImageTexturesResolvedAgainstTheScenesFolder) {
    std::vector<SceneImageFile> files = textureFiles(texturedIn("/scenes/tutorial"));
    ASSERT_EQ(files.size(), 3u);
    EXPECT_EQ(files[0].key, "materials[0].texture_image");
    EXPECT_EQ(files[0].path, "/scenes/tutorial/textures/wood.png");
    EXPECT_EQ(files[1].key, "materials[2].texture_image");
    EXPECT_EQ(files[2].key, "materials[3].texture_image");
}

TEST(TextureFiles, AMissingOrUnreadableFileIsAProblemNamedByItsKey) {
    std::vector<std::string> problems = textureProblems(texturedIn("/nonexistent-folder"));
    ASSERT_EQ(problems.size(), 3u);
    EXPECT_EQ(
        problems[0].rfind("materials[0].texture_image: cannot read image /nonexistent-folder/textures/wood.png", 0), 0u)
        << problems[0];
    EXPECT_EQ(problems[1], "materials[2].texture_image: an image texture needs an image file here");
}

// A 16 x 16 image, its top half red and its bottom half blue.
void writeRedOverBlue(const std::filesystem::path& path) {
    image::Image picture(16, 16);
    for (std::size_t i = 0; i < picture.pixelCount(); ++i) picture.rgb[3 * i + (i < 128 ? 0 : 2)] = 1.0f;
    image::writeImage(path, picture);
}

TEST(ImagePreviews, EachReadableFileHasAnUprightThumbnailOfAtMostTheSideAsked) {
    sdfwb::test::ScratchFolder folder;
    std::filesystem::create_directories(folder / "textures");
    writeRedOverBlue(folder / "textures/wood.png");
    scene::Scene s = texturedIn(folder.path().string());
    s.environment.map = scene::EnvironmentMapKind::Equirect;
    s.environment.image = "textures/wood.png";
    std::map<std::string, image::Image> previews = sceneImagePreviews(s, 4);
    // materials[2] names no file: no thumbnail; the others share one file
    ASSERT_EQ(previews.size(), 3u);
    for (const char* key : {"environment.image", "materials[0].texture_image", "materials[3].texture_image"}) {
        ASSERT_TRUE(previews.count(key)) << key;
        const image::Image& preview = previews.at(key);
        ASSERT_EQ(preview.width, 4) << key;
        ASSERT_EQ(preview.height, 4) << key;
        EXPECT_FLOAT_EQ(preview.rgb[0], 1.0f) << key << ": the top row is red";
        EXPECT_FLOAT_EQ(preview.rgb[preview.rgb.size() - 1], 1.0f) << key << ": the bottom row is blue";
    }
    EXPECT_EQ(sceneImagePreviews(s, 64).at("environment.image").width, 16);  // never larger than the image
}

TEST(TextureFiles, AnImageBumpMapIsAFileOfItsMaterialToo) {
    scene::Scene s = texturedIn("/scenes/tutorial");
    s.materials[1].bump = scene::BumpPattern::Image;
    s.materials[1].bumpImage = "heights/bricks.png";
    s.materials[2].bump = scene::BumpPattern::Image;  // no file named yet
    std::vector<SceneImageFile> files = textureFiles(s);
    ASSERT_EQ(files.size(), 5u);
    EXPECT_EQ(files[1].key, "materials[1].bump_image");
    EXPECT_EQ(files[1].path, "/scenes/tutorial/heights/bricks.png");
    EXPECT_EQ(files[3].key, "materials[2].bump_image");
    std::vector<std::string> problems = textureProblems(s);
    EXPECT_NE(std::find(problems.begin(), problems.end(),
                        "materials[2].bump_image: an image bump map needs an image file here"),
              problems.end());
    moveSceneDirectory(s, "/elsewhere");
    EXPECT_EQ(s.materials[1].bumpImage, "../scenes/tutorial/heights/bricks.png");
}

TEST(TextureFiles, ABumpMapsHeightsAreReadAsStoredAndItsTextureAsColour) {
    // one grey file, 128 of 255, as one material's texture and bump map
    sdfwb::test::ScratchFolder folder;
    image::Image grey(4, 4);
    for (float& value : grey.rgb) value = image::decodeSrgb8(128);
    image::writeImage(folder / "grey.png", grey);
    scene::Scene s;
    s.directory.path = folder.path().string();
    scene::Material m;
    m.name = "both";
    m.texture = scene::TexturePattern::Image;
    m.textureImage = "grey.png";
    m.bump = scene::BumpPattern::Image;
    m.bumpImage = "grey.png";
    s.materials.push_back(m);
    scene::Node ball = scene::Node::make(scene::NodeKind::Sphere);
    ball.set("material", std::string("both"));
    s.root.children.push_back(ball);
    Program p = compileScene(s);
    ASSERT_EQ(p.textureFiles.size(), 2u);  // the file once for each way it is read
    EXPECT_EQ(p.textureFiles[0].path, p.textureFiles[1].path);
    EXPECT_FALSE(p.textureFiles[0].heights);
    EXPECT_TRUE(p.textureFiles[1].heights);
    ResolvedImages images = resolveImages(p);
    ASSERT_EQ(images.textures.size(), 2u);
    EXPECT_FLOAT_EQ(images.textures[0]->texels[0].x, image::decodeSrgb8(128));  // about 0.216
    EXPECT_FLOAT_EQ(images.textures[1]->texels[0].x, 128.0f / 255.0f);          // half way up
    // its thumbnail shows the file's grey as stored
    const image::Image thumbnail = sceneImagePreviews(s, 4).at("materials[0].bump_image");
    EXPECT_EQ(image::encodeSrgb8(thumbnail.rgb[0]), 128);
    EXPECT_TRUE(textureProblems(s).empty());
}

TEST(TextureFiles, MovingTheSceneRebasesTheTexturesToo) {
    scene::Scene s = texturedIn("/scenes/tutorial");
    moveSceneDirectory(s, "/elsewhere");
    EXPECT_EQ(s.materials[0].textureImage, "../scenes/tutorial/textures/wood.png");
    EXPECT_EQ(textureFiles(s)[0].path, "/scenes/tutorial/textures/wood.png");
}

// The editor saves a scene whose texture is missing as the user left it: the
// name survives Save As into another folder (rebased) and the reload, and
// the scene still compiles and renders its placeholder.
TEST(TextureFiles, AMissingTextureKeepsItsNameThroughSaveAsAndReload) {
    test::ScratchFolder folder("sdfwb-missing-texture-");
    scene::Scene s = texturedIn((folder.path() / "scenes").string());
    scene::Node ball = scene::Node::make(scene::NodeKind::Sphere);
    ball.set("material", std::string("wood"));
    s.root.children.push_back(ball);
    std::filesystem::path saved = folder.path() / "elsewhere" / "saved.json";
    std::filesystem::create_directories(saved.parent_path());
    moveSceneDirectory(s, saved.parent_path());
    scene::saveSceneFile(s, saved);
    scene::Scene reloaded = scene::loadSceneFile(saved);
    EXPECT_EQ(reloaded.materials[0].textureImage, "../scenes/textures/wood.png");
    std::vector<SceneImageFile> files = textureFiles(reloaded);
    ASSERT_FALSE(files.empty());
    EXPECT_EQ(std::filesystem::weakly_canonical(files[0].path),
              std::filesystem::weakly_canonical(folder.path() / "scenes" / "textures" / "wood.png"));
    EXPECT_EQ(textureProblems(reloaded).size(), 3u);  // as before the save: two missing files, one unnamed
    ResolvedImages images = resolveImages(compileScene(reloaded));
    ASSERT_FALSE(images.textures.empty());
    EXPECT_GT(images.textures[0]->texels.size(), 0u);  // the placeholder
}

TEST(TextureFiles, MaterialsNamingOneFileShareItsImageInTheTexelBuffer) {
    scene::Scene s = texturedIn("/nonexistent-folder");
    s.materials[2].textureImage = "other.png";
    for (const char* name : {"wood", "oak", "unnamed"}) {
        scene::Node ball = scene::Node::make(scene::NodeKind::Sphere);
        ball.set("material", std::string(name));
        s.root.children.push_back(ball);
    }
    Program p = compileScene(s);
    ASSERT_EQ(p.textureFiles.size(), 2u);
    ASSERT_EQ(p.textureSlots.size(), 3u);
    EXPECT_EQ(p.textureSlots[0].file, 0);
    EXPECT_EQ(p.textureSlots[1].file, 0);
    EXPECT_EQ(p.textureSlots[2].file, 1);
    // unreadable: each file its own placeholder, one after the other
    ResolvedImages images = resolveImages(p);
    ASSERT_EQ(images.textures.size(), 2u);
    ASSERT_EQ(images.slots.size(), 3u);
    EXPECT_EQ(images.slots[0].second.x, 0.0);
    EXPECT_EQ(images.slots[2].second.x, static_cast<double>(images.textures[0]->texels.size()));
    EXPECT_EQ(images.slots[2].second.y, images.textures[1]->side);
}

TEST(TextureFiles, ASceneNamesAtMostSixteenImages) {
    scene::Scene s;
    for (int i = 0; i <= scene::kMaxTextureImages; ++i) {
        scene::Material m;
        m.name = "m" + std::to_string(i);
        m.texture = scene::TexturePattern::Image;
        m.textureImage = "image" + std::to_string(i) + ".png";
        s.materials.push_back(m);
    }
    std::vector<std::string> problems = scene::validateScene(s);
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_NE(problems[0].find("materials[16].texture_image"), std::string::npos) << problems[0];
    EXPECT_NE(problems[0].find("at most 16 texture and bump images"), std::string::npos) << problems[0];
    s.materials.back().textureImage = "image0.png";  // the same file again is no new image
    EXPECT_TRUE(scene::validateScene(s).empty());
    s.materials.back().bump = scene::BumpPattern::Image;  // a bump map's file counts too
    s.materials.back().bumpImage = "heights.png";
    problems = scene::validateScene(s);
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_NE(problems[0].find("materials[16].bump_image"), std::string::npos) << problems[0];
    // a texture's file as a bump map is read a second way: a second image
    s.materials.back().bumpImage = "image0.png";
    problems = scene::validateScene(s);
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_NE(problems[0].find("materials[16].bump_image"), std::string::npos) << problems[0];
}

}  // namespace
}  // namespace sdfwb::program
