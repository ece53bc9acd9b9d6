// What a flat mirror shows is filtered as if seen directly along the unfolded
// path: the floor's grid lines (material.glsl) and a material's filtered
// texture (texture.glsl) take their footprint from the distance the light
// travels from the eye, mirror included, and from the direction of the ray
// that sees them (the driver's footprintShift, sample_driver.glsl). A camera
// looking into a mirror sees, where the mirror is, the image a camera
// mirrored through the mirror's plane sees directly, flipped: left to right
// for a mirror standing on the floor, upside down for one on the ceiling.

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "cpu/cpu_renderer.h"
#include "image/image.h"
#include "program/compile_scene.h"
#include "scene/scene.h"

namespace sdfwb {
namespace {

using glm::dvec3;

constexpr int kWidth = 96, kHeight = 64;

// A mirror's face: the plane x = 0 (a wall facing +x) or y = 2 (a ceiling
// facing down), and the view into it: the camera's orbit about a target on
// that plane, so the mirrored camera (elevation or azimuth negated) aims at
// the same point.
struct Mirror {
    dvec3 centre, halfExtents;
    dvec3 target;
    double azimuth, elevation;
    bool flipsRows;  // the mirrored camera's image is upside down, else left to right
    scene::Camera mirroredCamera() const {
        scene::Camera c;
        c.target = target;
        c.azimuth = flipsRows ? azimuth : -azimuth;
        c.elevation = flipsRows ? -elevation : elevation;
        c.distance = 4.0;
        return c;
    }
};
void PrintTo(const Mirror& mirror, std::ostream* out) { *out << (mirror.flipsRows ? "ceiling" : "wall"); }

const Mirror kWall{{-0.05, 1.0, 0.0}, {0.05, 1.0, 3.0}, {0.0, 0.9, -0.4}, 60.0, 28.0, false};
const Mirror kCeiling{{0.0, 2.05, 0.0}, {4.0, 0.05, 4.0}, {0.0, 2.0, 0.0}, 30.0, -25.0, true};

// A floor of fine grid lines and a crate with a fine checker texture, both
// diffuse only under one directional light without shadows, so a surface's
// colour depends on where it is and on its footprint, not on the view. With
// `withMirror`, the perfect mirror stands in view; without, the mirrored
// camera looks at the room directly.
scene::Scene room(const Mirror& mirror, bool withMirror) {
    scene::Scene s;
    s.lights = {scene::Light{}};
    s.environment.ambient = dvec3(0.0);
    s.environment.background = dvec3(0.3, 0.5, 0.7);
    s.render.width = kWidth;
    s.render.height = kHeight;
    s.render.shadows = scene::ShadowMode::None;
    s.render.tracing = scene::Tracing::Plain;
    s.render.maxDistance = 1000.0;
    // hits and secondary rays' starts a few epsilons off the mirror shift what
    // it shows by about as much: far below the grid lines' width
    s.render.epsilon = 1e-5;

    scene::Material floor = scene::defaultMaterial();
    floor.name = "floor";
    floor.ambient = floor.specular = dvec3(0.0);
    floor.diffuse = dvec3(1.0);
    s.materials.push_back(floor);
    s.environment.ground.enabled = true;
    s.environment.ground.material = "floor";
    s.environment.ground.pattern = scene::GroundPattern::Grid;
    s.environment.ground.cellSize = 0.25;
    s.environment.ground.lineWidth = 0.02;
    s.environment.ground.secondColor = dvec3(0.0);

    scene::Material crate = floor;
    crate.name = "crate";
    crate.texture = scene::TexturePattern::Checker;
    crate.textureScale = 0.05;
    crate.textureColor = dvec3(0.0);
    s.materials.push_back(crate);
    scene::Node crateAt = scene::Node::make(scene::NodeKind::Translate);
    crateAt.set("offset", dvec3(3.0, 0.6, -2.5));
    scene::Node box = scene::Node::make(scene::NodeKind::Box);
    box.set("half_extents", dvec3(0.6));
    box.set("material", std::string("crate"));
    crateAt.children.push_back(box);
    s.root.children.push_back(crateAt);

    if (withMirror) {
        scene::Material chrome = floor;
        chrome.name = "chrome";
        chrome.diffuse = dvec3(0.0);
        chrome.reflectivity = 1.0;
        chrome.reflectionColor = dvec3(1.0);
        s.materials.push_back(chrome);
        scene::Node mirrorAt = scene::Node::make(scene::NodeKind::Translate);
        mirrorAt.set("offset", mirror.centre);
        scene::Node pane = scene::Node::make(scene::NodeKind::Box);
        pane.set("half_extents", mirror.halfExtents);
        pane.set("material", std::string("chrome"));
        mirrorAt.children.push_back(pane);
        s.root.children.push_back(mirrorAt);
        s.camera.target = mirror.target;
        s.camera.azimuth = mirror.azimuth;
        s.camera.elevation = mirror.elevation;
        s.camera.distance = 4.0;
    } else {
        s.camera = mirror.mirroredCamera();
    }
    return s;
}

image::Image render(const scene::Scene& s) {
    return cpu::renderCpu(program::compileScene(s), {.precision = render::Precision::Double}).frame.color;
}

float channel(const image::Image& image, int x, int y, int c) {
    return image.rgb[static_cast<size_t>(3 * (y * image.width + x) + c)];
}

class MirrorFootprint : public testing::TestWithParam<Mirror> {};

TEST_P(MirrorFootprint, AFlatMirrorShowsWhatTheMirroredCameraSeesFilteredAlike) {
    const Mirror& mirror = GetParam();
    scene::Scene withMirror = room(mirror, true);
    // where the mirror is: its face made a plain emissive red
    scene::Scene marked = withMirror;
    scene::Material& chrome = marked.materials.back();
    chrome.reflectivity = 0.0;
    chrome.emission = dvec3(1.0, 0.0, 0.0);
    const image::Image mask = render(marked);
    const image::Image seen = render(withMirror);
    const image::Image direct = render(room(mirror, false));
    auto directAt = [&](int x, int y, int c) {
        return mirror.flipsRows ? channel(direct, x, kHeight - 1 - y, c) : channel(direct, kWidth - 1 - x, y, c);
    };

    int pixels = 0, beyond = 0;
    double total = 0.0;
    float darkest = 1.0f, brightest = 0.0f;
    for (int y = 1; y + 1 < kHeight; ++y) {
        for (int x = 1; x + 1 < kWidth; ++x) {
            bool inside = true;  // the pixel and its neighbours see the mirror
            for (int dy = -1; dy <= 1; ++dy) {
                for (int dx = -1; dx <= 1; ++dx) {
                    inside =
                        inside && channel(mask, x + dx, y + dy, 1) < 0.01f && channel(mask, x + dx, y + dy, 0) > 0.5f;
                }
            }
            if (!inside) continue;
            ++pixels;
            darkest = std::min(darkest, directAt(x, y, 1));
            brightest = std::max(brightest, directAt(x, y, 1));
            double worst = 0.0;
            for (int c = 0; c < 3; ++c) {
                double difference = std::abs(channel(seen, x, y, c) - directAt(x, y, c));
                total += difference;
                worst = std::max(worst, difference);
            }
            beyond += worst > 8.0 / 255;
        }
    }
    ASSERT_GT(pixels, kWidth * kHeight / 8) << "the mirror fills too little of the view";
    ASSERT_GT(brightest - darkest, 0.3f) << "the mirror shows no pattern to filter";
    // measured from the floor point's own distance from the eye, the grid
    // seen in a mirror was filtered too little: 16.9/255 apart on the mean
    // and 1747 of 2820 pixels beyond 8/255 (wall), 13.1/255 and 2381 of 4311
    // (ceiling; the same with the shift's y left out); now 0.007/255 and
    // 0.016/255, none beyond
    EXPECT_LT(total / (3 * pixels), 0.5 / 255) << pixels << " pixels";
    EXPECT_LT(beyond, pixels / 200);
}

INSTANTIATE_TEST_SUITE_P(Mirrors, MirrorFootprint, testing::Values(kWall, kCeiling),
                         [](const testing::TestParamInfo<Mirror>& info) {
                             return info.param.flipsRows ? "Ceiling" : "Wall";
                         });

}  // namespace
}  // namespace sdfwb
