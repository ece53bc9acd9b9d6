// The reference's settings and its cache: the key follows what the image
// depends on and nothing else; cached frames come back whole or not at all.

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "tradeoff/reference.h"

namespace sdfwb::tradeoff {
namespace {

namespace fs = std::filesystem;

TEST(ReferenceScene, TightensEpsilonAndStepsAndKeepsAtLeastTheScenesAa) {
    scene::Scene s;
    s.render.aa = 2;
    scene::Scene r = referenceScene(s, {10, 1});
    EXPECT_DOUBLE_EQ(r.render.epsilon, s.render.epsilon / 10);
    EXPECT_EQ(r.render.maxSteps, s.render.maxSteps * 10);
    EXPECT_EQ(r.render.shadowSteps, s.render.shadowSteps * 10);
    EXPECT_EQ(r.render.aa, 2);
    EXPECT_EQ(referenceScene(s, {10, 3}).render.aa, 3);
    // every bounce the max_depth and ray_weight_cutoff knobs may ask for
    EXPECT_EQ(r.render.maxDepth, scene::kMaxTraceDepth);
    EXPECT_DOUBLE_EQ(r.render.rayWeightCutoff, s.render.rayWeightCutoff / 10);
}

TEST(ReferenceKey, ChangesWithContentAndSettingsButNotWithNames) {
    scene::Scene s;
    std::string key = referenceKey(s);
    EXPECT_EQ(key.size(), 16u);
    EXPECT_EQ(referenceKey(s), key);
    scene::Scene renamed = s;
    renamed.name = "other";
    renamed.description = "words";
    EXPECT_EQ(referenceKey(renamed), key);
    EXPECT_NE(referenceKey(s, "the shading code changed"), key);
    scene::Scene moved = s;
    moved.camera.azimuth += 1;
    EXPECT_NE(referenceKey(moved), key);
    scene::Scene tighter = s;
    tighter.render.epsilon /= 2;
    EXPECT_NE(referenceKey(tighter), key);
    scene::Scene bigger = s;
    bigger.render.width += 1;
    EXPECT_NE(referenceKey(bigger), key);
    scene::Scene edited = s;
    edited.root.children.push_back(scene::Node::make(scene::NodeKind::Sphere));
    EXPECT_NE(referenceKey(edited), key);
}

class ReferenceCache : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("sdfwb_refcache_" + std::to_string(::getpid()) + "_" +
                                            ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    fs::path dir_;
};

image::Frame smallFrame() {
    image::Frame f;
    f.color = image::Image(3, 2);
    for (size_t i = 0; i < f.color.rgb.size(); ++i) f.color.rgb[i] = 0.1f * float(i);
    f.steps = {1, 2, 3, 4, 5, 6};
    f.evaluations = {7, 8, 9, 10, 11, 12};
    f.coverage = {0, 0.25f, 1, 1, 0.5f, 0};
    f.depth = {0, 2, 3, 4, 5, 0};
    return f;
}

TEST_F(ReferenceCache, StoredFramesComeBackBitForBit) {
    image::Frame f = smallFrame();
    storeReference(dir_ / "nested", "abc", f);
    std::optional<image::Frame> back = loadReference(dir_ / "nested", "abc", 3, 2);
    ASSERT_TRUE(back);
    EXPECT_EQ(back->color.rgb, f.color.rgb);
    EXPECT_EQ(back->steps, f.steps);
    EXPECT_EQ(back->evaluations, f.evaluations);
    EXPECT_EQ(back->coverage, f.coverage);
    EXPECT_EQ(back->depth, f.depth);
    EXPECT_EQ(std::distance(fs::directory_iterator(dir_ / "nested"), {}), 1);  // no temporary left
}

TEST_F(ReferenceCache, MissingWrongSizeOrTruncatedEntriesAreMisses) {
    EXPECT_FALSE(loadReference(dir_, "abc", 3, 2));
    storeReference(dir_, "abc", smallFrame());
    EXPECT_FALSE(loadReference(dir_, "abc", 2, 3));
    EXPECT_FALSE(loadReference(dir_, "other", 3, 2));
    fs::resize_file(dir_ / "abc.ref", fs::file_size(dir_ / "abc.ref") - 4);
    EXPECT_FALSE(loadReference(dir_, "abc", 3, 2));
}

}  // namespace
}  // namespace sdfwb::tradeoff
