// CPU/GPU parity on every shipped scene, with the thresholds of
// image/compare.h (kParityThresholds), and the hard-case gate against the
// double-precision reference for scenes/hard/. Prints the parity table.

#include <filesystem>
#include <iostream>

#include <gtest/gtest.h>

#include "cpu/cpu_backend.h"
#include "gl/gl_backend.h"
#include "gl_test_support.h"
#include "image/image_io.h"
#include "parity/parity.h"
#include "scene/scene_json.h"
#include "support/scene_files.h"
#include "support/source_tree.h"

namespace sdfwb {
namespace {

class Parity : public test::GlTest, public ::testing::WithParamInterface<test::SceneFile> {};

// On a failure, the expected (CPU), actual (GL) and difference images go to
// the test-output folder, named after the test, and the paths are printed.
void keepFailureImages(const parity::ParityResult& r, const std::string& name) {
    if (!::testing::Test::HasFailure()) return;
    for (const std::filesystem::path& path :
         parity::writeFailureImages(r, std::filesystem::path(sdfwb::test::outputDir()) / "parity", name)) {
        std::cout << "wrote " << path.string() << "\n";
    }
}

TEST_P(Parity, BackendsAgree) {
    const test::SceneFile& file = GetParam();
    scene::Scene s = scene::loadSceneFile(file.path());
    cpu::CpuBackend cpu;
    gl::GlBackend glBackend(context());
    parity::ParityOptions options{.width = 320, .height = 180, .aa = 2, .reference = file.isHardCase()};
    std::optional<scene::Scene> intended = options.reference ? parity::loadIntendedScene(file.path()) : std::nullopt;
    options.intended = intended ? &*intended : nullptr;
    parity::ParityResult r = parity::measureParity(s, cpu, glBackend, options);
    std::cout << parity::tableHeader(options.reference) << parity::tableRow(file.relative, r, options.reference);
    EXPECT_EQ(r.cpuNonFinite, 0u);
    EXPECT_EQ(r.glNonFinite, 0u);
    if (options.reference) {
        EXPECT_TRUE(r.passesHardGate) << "hard-case gate failed";
    }
    {
        const image::ParityThresholds& t = image::kParityThresholds;
        EXPECT_LE(r.glVsCpu.percentAbove(t.failLevel), t.failPercent);
        EXPECT_LE(r.glVsCpu.maxAbs, t.hardFailLevel);
        EXPECT_LT(r.glVsCpu.meanAbs, t.maxMeanLevel);
    }
    keepFailureImages(r, file.testName());
}

INSTANTIATE_TEST_SUITE_P(Scenes, Parity, ::testing::ValuesIn(test::allSceneFiles()),
                         [](const ::testing::TestParamInfo<test::SceneFile>& info) { return info.param.testName(); });

// A scene of 1000 nodes (500 translated spheres in a union) through both backends.
class LargeScene : public test::GlTest {};

TEST_F(LargeScene, ThousandNodeSceneHasParity) {
    scene::Scene s;
    s.camera = {.target = {0, 0, 0}, .azimuth = 20, .elevation = 30, .distance = 14, .fov = 45};
    for (int i = 0; i < 500; ++i) {
        scene::Node translate = scene::Node::make(scene::NodeKind::Translate);
        translate.set("offset", glm::dvec3((i % 10) - 4.5, ((i / 10) % 5) - 2.0, (i / 50) - 4.5));
        scene::Node sphere = scene::Node::make(scene::NodeKind::Sphere);
        sphere.set("radius", 0.2 + 0.002 * i);
        translate.children.push_back(sphere);
        s.root.children.push_back(translate);
    }
    cpu::CpuBackend cpu;
    gl::GlBackend glBackend(context());
    parity::ParityResult r = parity::measureParity(s, cpu, glBackend, {.width = 96, .height = 54, .aa = 1});
    std::cout << parity::tableHeader(false) << parity::tableRow("1000 nodes (generated)", r, false);
    EXPECT_TRUE(r.passes);
    EXPECT_GT(r.glHitRatio, 0.2);
    keepFailureImages(r, "thousand_nodes");
}

TEST(ParityFailureImages, ExpectedActualAndDifferenceAreWritten) {
    parity::ParityResult r;
    r.cpuColor = image::Image(4, 2);
    r.glColor = image::Image(4, 2);
    r.glColor.rgb[3] = 1.0f;  // pixel (1, 0) red in the GL render
    std::vector<std::filesystem::path> paths =
        parity::writeFailureImages(r, std::filesystem::path(sdfwb::test::outputDir()) / "parity", "synthetic");
    ASSERT_EQ(paths.size(), 3u);
    EXPECT_EQ(image::readImage(paths[0]).rgb, r.cpuColor.rgb);
    EXPECT_EQ(image::readImage(paths[1]).rgb, r.glColor.rgb);
    image::Image diff = image::readImage(paths[2]);
    ASSERT_EQ(diff.width, 4);
    EXPECT_EQ(diff.rgb[0], 0.0f) << "equal pixels are black";
    EXPECT_EQ(diff.rgb[3], 1.0f) << "a full-scale difference is red";
}

}  // namespace
}  // namespace sdfwb
