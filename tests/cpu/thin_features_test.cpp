// Zero-thickness slivers are not surfaces, from any angle; thin solids and
// planes seen at grazing angles still are (docs/rendering.md, "Thin features
// and slivers"). A disc where two cylinders only touch cap to cap, seen
// nearly edge-on, was drawn as a line: rays grazing its plane first get within
// epsilon of it from one side, where the normal's four samples see a plane.

#include <string>

#include <gtest/gtest.h>

#include "cpu/cpu_renderer.h"
#include "image/image.h"
#include "program/compile_scene.h"
#include "scene/scene.h"

namespace sdfwb {
namespace {

using glm::dvec3;
using scene::Node;
using scene::NodeKind;

Node translated(dvec3 offset, Node child) {
    Node t = Node::make(NodeKind::Translate);
    t.set("offset", offset);
    t.children.push_back(std::move(child));
    return t;
}

Node cylinder(double halfHeight) {
    Node c = Node::make(NodeKind::Cylinder);
    c.set("radius", 0.6);
    c.set("half_height", halfHeight);
    return c;
}

// Two cylinders stacked along y whose caps are `gap` apart (negative: they
// overlap by -gap), intersected: a disc of thickness -gap at y = 0.5, or
// nothing. No ground: every pixel not on the disc is background.
scene::Scene stackedCylinders(double gap, double elevationDegrees) {
    scene::Scene s;
    s.render.width = 96;
    s.render.height = 64;
    s.render.aa = 1;
    s.render.shadows = scene::ShadowMode::None;
    s.render.aoSamples = 0;
    s.environment.ground.enabled = false;
    s.camera = {.target = {0, 0.5, 0}, .azimuth = 30, .elevation = elevationDegrees, .distance = 4, .fov = 40};
    Node intersection = Node::make(NodeKind::Intersection);
    intersection.children.push_back(cylinder(0.5));
    intersection.children.push_back(translated({0, 1.0 + gap, 0}, cylinder(0.5)));
    s.root.children.push_back(intersection);
    return s;
}

double coveredPixels(const scene::Scene& s, render::Precision precision) {
    render::RenderControl control;
    control.precision = precision;
    const image::Frame frame = cpu::renderCpu(program::compileScene(s), control).frame;
    double sum = 0;
    for (float c : frame.coverage) sum += c;
    return sum;
}

class ThinFeatures : public ::testing::TestWithParam<double> {};

TEST_P(ThinFeatures, ACapToCapSliverIsNotASurfaceFromAnyElevation) {
    const double elevation = GetParam();
    EXPECT_EQ(coveredPixels(stackedCylinders(0.0, elevation), render::Precision::Float), 0.0)
        << "elevation " << elevation;
    EXPECT_EQ(coveredPixels(stackedCylinders(0.0, elevation), render::Precision::Double), 0.0)
        << "elevation " << elevation;
}

TEST_P(ThinFeatures, AThinDiscIsStillASurfaceFromAnyElevation) {
    const double elevation = GetParam();
    EXPECT_GT(coveredPixels(stackedCylinders(-0.02, elevation), render::Precision::Float), 10.0)
        << "elevation " << elevation;
}

// From nearly edge-on (the sliver's line) to steep.
INSTANTIATE_TEST_SUITE_P(Elevations, ThinFeatures, ::testing::Values(0.5, 1.0, 1.5, 2.0, 2.5, 3.0, 4.0, 6.0, 8.0, 12.0, 30.0, 80.0));

}  // namespace
}  // namespace sdfwb
