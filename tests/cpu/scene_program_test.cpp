// Compiled scenes evaluated by the CPU interpreter: fold order of n-ary booleans,
// transforms folded into the camera-relative offset, far-from-origin precision.

#include <algorithm>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "cpu/cpu_renderer.h"
#include "program/compile_scene.h"
#include "scene/scene_json.h"

namespace sdfwb {
namespace {

using scene::Node;
using scene::NodeKind;

Node sphereAt(glm::dvec3 centre, double radius) {
    Node translate = Node::make(NodeKind::Translate);
    translate.set("offset", centre);
    Node sphere = Node::make(NodeKind::Sphere);
    sphere.set("radius", radius);
    translate.children.push_back(sphere);
    return translate;
}

// Distance at a world point, through the compiled program (march coordinates are eye-relative).
double distanceAt(const scene::Scene& s, glm::dvec3 world, render::Precision precision = render::Precision::Double) {
    program::Program p = program::compileScene(s);
    glm::dvec3 eye = s.camera.target + glm::dvec3(0, 0, s.camera.distance);  // azimuth 0, elevation 0
    return cpu::evaluateDistance(p, world - eye, precision);
}

scene::Scene sceneWithRoot(Node root) {
    scene::Scene s;
    s.camera.azimuth = 0;
    s.camera.elevation = 0;
    s.root = std::move(root);
    return s;
}

TEST(SceneProgram, DifferenceFoldsFirstMinusEveryLaterChild) {
    Node difference = Node::make(NodeKind::Difference);
    difference.children = {sphereAt({0, 0, 0}, 2), sphereAt({1.5, 0, 0}, 1), sphereAt({-1.5, 0, 0}, 1)};
    scene::Scene s = sceneWithRoot(difference);
    for (glm::dvec3 p : {glm::dvec3(0, 0, 0), glm::dvec3(1.2, 0.3, 0), glm::dvec3(-1.4, 0, 0.2), glm::dvec3(0, 3, 0)}) {
        double a = glm::length(p) - 2, b = glm::length(p - glm::dvec3(1.5, 0, 0)) - 1,
               c = glm::length(p - glm::dvec3(-1.5, 0, 0)) - 1;
        EXPECT_NEAR(distanceAt(s, p), std::max(std::max(a, -b), -c), 1e-12);
    }
}

TEST(SceneProgram, UnionAndIntersectionAreNary) {
    for (NodeKind kind : {NodeKind::Union, NodeKind::Intersection}) {
        Node op = Node::make(kind);
        op.children = {sphereAt({0, 0, 0}, 1), sphereAt({0.5, 0, 0}, 1), sphereAt({0, 0.5, 0}, 1)};
        scene::Scene s = sceneWithRoot(op);
        glm::dvec3 p(0.3, -0.4, 2);
        double a = glm::length(p) - 1, b = glm::length(p - glm::dvec3(0.5, 0, 0)) - 1,
               c = glm::length(p - glm::dvec3(0, 0.5, 0)) - 1;
        double expected = kind == NodeKind::Union ? std::min({a, b, c}) : std::max({a, b, c});
        EXPECT_NEAR(distanceAt(s, p), expected, 1e-12);
    }
}

TEST(SceneProgram, RotateThenScaleKeepDistancesExact) {
    Node rotate = Node::make(NodeKind::Rotate);
    rotate.set("angles", glm::dvec3(0, 90, 0));
    Node scale = Node::make(NodeKind::Scale);
    scale.set("factor", 2.0);
    Node box = Node::make(NodeKind::Box);
    box.set("half_extents", glm::dvec3(1, 0.5, 0.25));
    scale.children.push_back(box);
    rotate.children.push_back(scale);
    scene::Scene s = sceneWithRoot(sphereAt({0, 0, 0}, 1));
    s.root = Node::make(NodeKind::Translate);
    s.root.set("offset", glm::dvec3(3, 0, 0));
    s.root.children.push_back(rotate);
    // the box scaled by 2 is 2 x 1 x 0.5; rotated 90 degrees about y its x extent is 0.5, z extent 2
    EXPECT_NEAR(distanceAt(s, {3 + 0.5 + 1, 0, 0}), 1.0, 1e-12);
    EXPECT_NEAR(distanceAt(s, {3, 0, 2 + 1.5}), 1.5, 1e-12);
}

TEST(SceneProgram, FarFromTheOriginTheFloatBuildKeepsPrecision) {
    // a unit sphere 1e4 units away, camera next to it: translations fold into the
    // eye-relative offset in double, so float evaluation stays accurate near the eye
    scene::Scene s = sceneWithRoot(sphereAt({1e4, 1e4, -1e4}, 1));
    s.camera.target = {1e4, 1e4, -1e4};
    s.camera.distance = 3;
    glm::dvec3 probe(1e4 + 0.0123, 1e4 + 1.5, -1e4 + 0.0456);
    double exact = glm::length(probe - glm::dvec3(1e4, 1e4, -1e4)) - 1;
    EXPECT_NEAR(distanceAt(s, probe, render::Precision::Float), exact, 1e-5);
}

TEST(SceneProgram, ImplicitIsTheSolidOrASheetAroundTheSurface) {
    // F = x^2 + y^2 + z^2 - 1: |F| / |grad F| = |r^2 - 1| / 2r, exact enough near r = 1
    Node implicit = Node::make(NodeKind::Polynomial);
    implicit.set("formula", std::string("x^2 + y^2 + z^2 - 1"));
    implicit.set("max_step", 10.0);
    scene::Scene solid = sceneWithRoot(implicit);
    implicit.set("sheet_thickness", 0.2);
    scene::Scene sheet = sceneWithRoot(implicit);
    for (double r : {0.5, 0.9, 1.0, 1.1, 1.3}) {
        glm::dvec3 p(0, r * 0.6, r * 0.8);
        double bound = std::abs(r * r - 1) / (2 * r);
        EXPECT_NEAR(distanceAt(solid, p), r < 1 ? -bound : bound, 1e-12) << r;
        // the sheet: inside within 0.1 of F = 0 on both sides, outside beyond
        // (its steps are capped at its thickness: tests/cpu/implicit_surface_test.cpp)
        EXPECT_NEAR(distanceAt(sheet, p), bound - 0.1, 1e-12) << r;
    }
    // the box clips the sheet too: at z = 1.1 the sheet is inside, the box not
    sheet.root.set("bounds_max", glm::dvec3(1.5, 1.5, 1.05));
    EXPECT_NEAR(distanceAt(sheet, glm::dvec3(0, 0, 1.1)), 0.05, 1e-12);
}

TEST(SceneProgram, EmptyUnionIsFarAway) {
    scene::Scene s = sceneWithRoot(Node::make(NodeKind::Union));
    EXPECT_GT(distanceAt(s, {0, 0, 0}), 1e9);
}

}  // namespace
}  // namespace sdfwb
