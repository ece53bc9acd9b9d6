// What a flat mirror shows is filtered as if seen directly along the unfolded
// path: the floor's grid lines (material.glsl) and a material's filtered
// texture (texture.glsl) take their footprint from the distance the light
// travels from the eye, mirror included, and from the direction of the ray
// that sees them (the driver's footprintShift, sample_driver.glsl). A camera
// looking into a mirror at the plane x = 0 sees, where the mirror is, the
// image a camera mirrored through that plane sees directly, flipped left to
// right.

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

// A floor of fine grid lines and a crate with a fine checker texture, both
// diffuse only under one directional light without shadows, so a surface's
// colour depends on where it is and on its footprint, not on the view. With
// `mirror`, a perfect mirror whose face is the plane x = 0 stands in view.
scene::Scene room(bool mirror, double azimuth) {
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

    scene::Material chrome = floor;
    chrome.name = "chrome";
    chrome.diffuse = dvec3(0.0);
    chrome.reflectivity = 1.0;
    chrome.reflectionColor = dvec3(1.0);
    s.materials.push_back(chrome);
    scene::Node mirrorAt = scene::Node::make(scene::NodeKind::Translate);
    mirrorAt.set("offset", mirror ? dvec3(-0.05, 1.0, 0.0) : dvec3(-0.05, -50.0, 0.0));
    scene::Node pane = scene::Node::make(scene::NodeKind::Box);
    pane.set("half_extents", dvec3(0.05, 1.0, 3.0));
    pane.set("material", std::string("chrome"));
    mirrorAt.children.push_back(pane);
    s.root.children.push_back(mirrorAt);

    s.camera.target = dvec3(0.0, 0.9, -0.4);  // on the mirror's plane: the mirrored camera aims at it too
    s.camera.azimuth = azimuth;
    s.camera.elevation = 28.0;
    s.camera.distance = 4.0;
    return s;
}

image::Image render(const scene::Scene& s) {
    return cpu::renderCpu(program::compileScene(s), {.precision = render::Precision::Double}).frame.color;
}

float channel(const image::Image& image, int x, int y, int c) {
    return image.rgb[static_cast<size_t>(3 * (y * image.width + x) + c)];
}

TEST(MirrorFootprint, AFlatMirrorShowsWhatTheMirroredCameraSeesFilteredAlike) {
    // the camera on the +x side, looking into the mirror at a slant
    const double azimuth = 60.0;
    scene::Scene withMirror = room(true, azimuth);
    // where the mirror is: its colour made a plain red
    scene::Scene marked = withMirror;
    scene::Material& chrome = marked.materials.back();
    chrome.reflectivity = 0.0;
    chrome.diffuse = dvec3(1.0, 0.0, 0.0);
    const image::Image mask = render(marked);
    const image::Image seen = render(withMirror);
    const image::Image direct = render(room(false, -azimuth));

    int pixels = 0, patterned = 0, beyond = 0;
    double total = 0.0;
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
            // darker than the bare floor in the light (n.l = 0.81): grid lines, the crate
            patterned += channel(direct, kWidth - 1 - x, y, 1) < 0.78f;
            double worst = 0.0;
            for (int c = 0; c < 3; ++c) {
                double difference = std::abs(channel(seen, x, y, c) - channel(direct, kWidth - 1 - x, y, c));
                total += difference;
                worst = std::max(worst, difference);
            }
            beyond += worst > 8.0 / 255;
        }
    }
    ASSERT_GT(pixels, kWidth * kHeight / 8) << "the mirror fills too little of the view";
    ASSERT_GT(patterned, pixels / 4) << "too few pixels see grid lines or the crate";
    // measured from the floor point's own distance from the eye, the grid
    // seen in the mirror was filtered too little: 16.9/255 apart on the
    // mean, 1747 of 2820 pixels beyond 8/255; now 0.007/255 and none
    EXPECT_LT(total / (3 * pixels), 0.5 / 255) << pixels << " pixels";
    EXPECT_LT(beyond, pixels / 200);
}

}  // namespace
}  // namespace sdfwb
