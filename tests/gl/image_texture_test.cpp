// Image textures through both backends (program/scene_images.h and the shared
// sampler): a box face seen head on shows its image's quadrants where they
// belong, upright; a formula shows its image triplanar; a missing file is
// named and renders as the placeholder; and the two backends agree. The
// images are written by the test, in colours that survive 8-bit files.

#include <filesystem>

#include <gtest/gtest.h>

#include "cpu/cpu_backend.h"
#include "gl/gl_backend.h"
#include "gl_test_support.h"
#include "image/image_io.h"
#include "parity/parity.h"
#include "program/compile_scene.h"
#include "program/scene_images.h"
#include "support/scratch_folder.h"

namespace sdfwb {
namespace {

// the image's quadrants as seen: top left, top right, bottom left, bottom right
const glm::vec3 kQuadrants[] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}};

glm::vec3 pixel(const image::Image& image, int x, int y) {
    const float* p =
        &image.rgb[3 * (static_cast<size_t>(y) * static_cast<size_t>(image.width) + static_cast<size_t>(x))];
    return {p[0], p[1], p[2]};
}

void expectColour(glm::vec3 got, glm::vec3 want, const char* where) {
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], 2e-3) << where << " channel " << c;
}

class ImageTexture : public test::GlTest {
protected:
    test::ScratchFolder folder{"sdfwb_image_texture_"};

    void SetUp() override {
        test::GlTest::SetUp();
        image::Image quadrants(16, 16);  // rows from the top
        for (int y = 0; y < 16; ++y) {
            for (int x = 0; x < 16; ++x) {
                glm::vec3 c = kQuadrants[(y < 8 ? 0 : 2) + (x < 8 ? 0 : 1)];
                for (int k = 0; k < 3; ++k)
                    quadrants.rgb[3 * static_cast<size_t>(y * 16 + x) + static_cast<size_t>(k)] = c[k];
            }
        }
        image::writeImage(folder / "quadrants.png", quadrants);
    }

    // One primitive seen along -z, lit by a white light from the eye, with
    // a white diffuse colour and nothing else: a face towards the eye shows
    // its texture's colour (n . l = 1).
    scene::Scene flatLit(scene::Node shape) const {
        scene::Scene s;
        s.directory.path = folder.path().string();
        s.camera = {.target = {0, 0, 0}, .azimuth = 0, .elevation = 0, .distance = 5, .fov = 40};
        s.lights = {scene::Light{.direction = {0, 0, 1}, .color = glm::dvec3(1), .softness = 8}};
        s.render.shadows = scene::ShadowMode::None;
        s.render.aoSamples = 0;
        s.environment.ambient = glm::dvec3(0);
        s.environment.background = glm::dvec3(0);
        scene::Material m;
        m.name = "textured";
        m.diffuse = glm::dvec3(1);
        m.ambient = m.specular = glm::dvec3(0);
        m.texture = scene::TexturePattern::Image;
        m.textureImage = "quadrants.png";
        s.materials.push_back(m);
        shape.set("material", std::string("textured"));
        s.root.children.push_back(shape);
        return s;
    }

    parity::ParityResult render(const scene::Scene& s) {
        cpu::CpuBackend cpu;
        gl::GlBackend glBackend(context());
        return parity::measureParity(s, cpu, glBackend, {.width = 64, .height = 64, .aa = 1});
    }

    // Both backends agree and show the image upright on the face towards the
    // eye, which spans pixels 13 to 51: each quadrant a quarter in from its corner.
    void expectUprightImage(const scene::Scene& s) {
        parity::ParityResult r = render(s);
        EXPECT_TRUE(r.passes);
        for (const image::Image* frame : {&r.cpuColor, &r.glColor}) {
            expectColour(pixel(*frame, 22, 22), kQuadrants[0], "top left");
            expectColour(pixel(*frame, 42, 22), kQuadrants[1], "top right");
            expectColour(pixel(*frame, 22, 42), kQuadrants[2], "bottom left");
            expectColour(pixel(*frame, 42, 42), kQuadrants[3], "bottom right");
        }
    }
};

TEST_F(ImageTexture, ABoxFaceSeenHeadOnShowsItsImageUpright) {
    scene::Node box = scene::Node::make(scene::NodeKind::Box);
    box.set("half_extents", glm::dvec3(1.2));
    scene::Scene s = flatLit(box);
    EXPECT_TRUE(program::sceneImageProblems(s).empty());
    expectUprightImage(s);
}

TEST_F(ImageTexture, AFormulaShowsItsImageTriplanarAlongItsNormal) {
    // a distance formula for a box from (0, 0) to (2.4, 2.4) in x and y: its
    // front face is projected along z, one tile of texture_scale 2.4 from the origin
    scene::Node formula = scene::Node::make(scene::NodeKind::Sdf);
    formula.set("formula", std::string("let q = abs(p - vec3(1.2, 1.2, 0)) - vec3(1.2, 1.2, 1.2); "
                                       "length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0)"));
    scene::Scene s = flatLit(formula);
    s.materials[0].textureScale = 2.4;
    s.camera.target = glm::dvec3(1.2, 1.2, 0);
    expectUprightImage(s);
}

TEST_F(ImageTexture, WithTextureSpecularTheImageColoursTheHighlightToo) {
    // lit and seen head on, a near-zero shininess makes the highlight the
    // specular colour itself: the image with texture_specular, white without
    scene::Node box = scene::Node::make(scene::NodeKind::Box);
    box.set("half_extents", glm::dvec3(1.2));
    scene::Scene s = flatLit(box);
    s.materials[0].diffuse = glm::dvec3(0);
    s.materials[0].specular = glm::dvec3(1);
    s.materials[0].shininess = 1e-4;
    s.materials[0].textureSpecular = true;
    expectUprightImage(s);
    s.materials[0].textureSpecular = false;
    parity::ParityResult plain = render(s);
    EXPECT_TRUE(plain.passes);
    expectColour(pixel(plain.cpuColor, 22, 22), glm::vec3(1), "top left, untextured highlight");
    expectColour(pixel(plain.glColor, 42, 42), glm::vec3(1), "bottom right, untextured highlight");
}

// A grey height map on the box's front face, 16 x 16 texels: grey(x) for
// column x (rows alike).
void writeHeightMap(const std::filesystem::path& path, float (*grey)(int)) {
    image::Image heights(16, 16);
    for (int y = 0; y < 16; ++y) {
        for (int x = 0; x < 16; ++x) {
            for (int c = 0; c < 3; ++c)
                heights.rgb[3 * static_cast<size_t>(y * 16 + x) + static_cast<size_t>(c)] = grey(x);
        }
    }
    image::writeImage(path, heights);
}

TEST_F(ImageTexture, AConstantHeightMapLeavesTheImageBitForBit) {
    writeHeightMap(folder / "flat.png", [](int) { return 0.5f; });
    scene::Node box = scene::Node::make(scene::NodeKind::Box);
    box.set("half_extents", glm::dvec3(1.2));
    scene::Scene plain = flatLit(box);
    plain.lights[0].direction = {-0.6, 0.3, 1};  // not along the normal, so a tilt would show
    scene::Scene bumped = plain;
    bumped.materials[0].bump = scene::BumpPattern::Image;
    bumped.materials[0].bumpImage = "flat.png";
    bumped.materials[0].bumpDepth = 1.0;
    EXPECT_EQ(program::compileScene(bumped).materialSamplesPerHit(), 5);
    parity::ParityResult a = render(plain), b = render(bumped);
    EXPECT_TRUE(b.passes);
    EXPECT_EQ(a.cpuColor.rgb, b.cpuColor.rgb);
    EXPECT_EQ(a.glColor.rgb, b.glColor.rgb);
}

TEST_F(ImageTexture, AHeightMapRisingToTheRightTiltsTheNormalToTheLeft) {
    // n' = n minus the height's gradient: a face rising to the right faces
    // left, so a light from the left brightens it and one from the right darkens it
    writeHeightMap(folder / "ramp.png", [](int x) { return static_cast<float>(x) / 15.0f; });
    scene::Node box = scene::Node::make(scene::NodeKind::Box);
    box.set("half_extents", glm::dvec3(1.2));
    for (double side : {-1.0, 1.0}) {
        scene::Scene plain = flatLit(box);
        plain.materials[0].texture = scene::TexturePattern::None;
        plain.lights[0].direction = {0.6 * side, 0, 1};
        scene::Scene bumped = plain;
        bumped.materials[0].bump = scene::BumpPattern::Image;
        bumped.materials[0].bumpImage = "ramp.png";
        bumped.materials[0].bumpDepth = 1.2;  // a slope of 1/2 across the 2.4-wide face
        parity::ParityResult a = render(plain), b = render(bumped);
        EXPECT_TRUE(b.passes);
        for (const auto& [flat, tilted] : {std::pair{&a.cpuColor, &b.cpuColor}, std::pair{&a.glColor, &b.glColor}}) {
            float before = pixel(*flat, 32, 32).x, after = pixel(*tilted, 32, 32).x;
            if (side < 0) {
                EXPECT_GT(after, before + 0.05f) << "light from the left";
            } else {
                EXPECT_LT(after, before - 0.05f) << "light from the right";
            }
        }
    }
}

TEST_F(ImageTexture, AMissingFileIsNamedAndRendersAsThePlaceholder) {
    scene::Node sphere = scene::Node::make(scene::NodeKind::Sphere);
    scene::Scene s = flatLit(sphere);
    s.materials[0].textureImage = "nowhere.png";
    std::vector<std::string> problems = program::sceneImageProblems(s);
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_EQ(problems[0].rfind("materials[0].texture_image: cannot read image ", 0), 0u) << problems[0];
    EXPECT_NE(problems[0].find("nowhere.png"), std::string::npos);
    parity::ParityResult r = render(s);
    EXPECT_TRUE(r.passes);
    EXPECT_EQ(r.cpuNonFinite, 0u);
    glm::vec3 centre = pixel(r.cpuColor, 32, 32);  // magenta or black, never the missing image
    EXPECT_NEAR(centre.y, 0.0, 1e-3);
}

}  // namespace
}  // namespace sdfwb
