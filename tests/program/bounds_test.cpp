// Bounds of scene subtrees (program/bounds.cpp) against boxes computed by hand.

#include <gtest/gtest.h>

#include "program/bounds.h"

namespace sdfwb {
namespace {

using glm::dvec3;
using program::Bounds;
using program::nodeBounds;
using scene::Node;
using scene::NodeKind;

Node sphere(double radius) {
    Node n = Node::make(NodeKind::Sphere);
    n.set("radius", radius);
    return n;
}

Node box(dvec3 half) {
    Node n = Node::make(NodeKind::Box);
    n.set("half_extents", half);
    return n;
}

Node with(NodeKind kind, std::vector<Node> children) {
    Node n = Node::make(kind);
    n.children = std::move(children);
    return n;
}

void expectBox(const Bounds& b, dvec3 lo, dvec3 hi) {
    ASSERT_FALSE(b.empty);
    ASSERT_FALSE(b.infinite);
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(b.min[i], lo[i], 1e-12) << "min[" << i << "]";
        EXPECT_NEAR(b.max[i], hi[i], 1e-12) << "max[" << i << "]";
    }
}

TEST(Bounds, PrimitivesAreCentredOnTheirOrigin) {
    expectBox(nodeBounds(sphere(2)), dvec3(-2), dvec3(2));
    expectBox(nodeBounds(box(dvec3(1, 2, 3))), dvec3(-1, -2, -3), dvec3(1, 2, 3));
    Node torus = Node::make(NodeKind::Torus);  // R 1, r 0.25
    expectBox(nodeBounds(torus), dvec3(-1.25, -0.25, -1.25), dvec3(1.25, 0.25, 1.25));
    Node cone = Node::make(NodeKind::Cone);
    cone.set("angle", 45.0);
    cone.set("height", 2.0);
    expectBox(nodeBounds(cone), dvec3(-2, -2, -2), dvec3(2, 0, 2));
    EXPECT_TRUE(nodeBounds(Node::make(NodeKind::Plane)).infinite);
    EXPECT_TRUE(nodeBounds(Node::make(NodeKind::Sdf)).infinite);
}

TEST(Bounds, BooleansMergeIntersectOrKeepTheFirstChild) {
    Node moved = with(NodeKind::Translate, {sphere(1)});
    moved.set("offset", dvec3(3, 0, 0));
    expectBox(nodeBounds(with(NodeKind::Union, {sphere(1), moved})), dvec3(-1), dvec3(4, 1, 1));
    expectBox(nodeBounds(with(NodeKind::Intersection, {box(dvec3(2)), moved})), dvec3(2, -1, -1), dvec3(2, 1, 1));
    EXPECT_TRUE(nodeBounds(with(NodeKind::Intersection, {sphere(1), with(NodeKind::Translate, {sphere(1)})}))
                    .intersected(Bounds::box(dvec3(5), dvec3(6)))
                    .empty);
    expectBox(nodeBounds(with(NodeKind::Difference, {sphere(1), moved})), dvec3(-1), dvec3(1));
    Node smooth = with(NodeKind::SmoothUnion, {sphere(1), moved});
    smooth.set("k", 0.5);
    expectBox(nodeBounds(smooth), dvec3(-1.5), dvec3(4.5, 1.5, 1.5));
    EXPECT_TRUE(nodeBounds(with(NodeKind::Union, {})).empty);
    EXPECT_TRUE(nodeBounds(with(NodeKind::Union, {sphere(1), Node::make(NodeKind::Plane)})).infinite);
}

TEST(Bounds, AffineOperatorsMoveTheBox) {
    Node rotated = with(NodeKind::Rotate, {box(dvec3(2, 1, 1))});
    rotated.set("angles", dvec3(0, 0, 90));
    expectBox(nodeBounds(rotated), dvec3(-1, -2, -1), dvec3(1, 2, 1));
    Node scaled = with(NodeKind::Scale, {sphere(1)});
    scaled.set("factor", 3.0);
    expectBox(nodeBounds(scaled), dvec3(-3), dvec3(3));
}

TEST(Bounds, DeformingOperatorsGrowTheBox) {
    Node rounded = with(NodeKind::Round, {box(dvec3(1))});
    rounded.set("radius", 0.5);
    expectBox(nodeBounds(rounded), dvec3(-1.5), dvec3(1.5));
    Node displaced = with(NodeKind::Displace, {box(dvec3(1))});
    displaced.set("amplitude", -0.2);
    expectBox(nodeBounds(displaced), dvec3(-1.2), dvec3(1.2));
    Node elongated = with(NodeKind::Elongate, {sphere(1)});
    elongated.set("h", dvec3(2, 0, 0));
    expectBox(nodeBounds(elongated), dvec3(-3, -1, -1), dvec3(3, 1, 1));
    // a twist about y keeps y and sweeps the box's corners round the axis
    Node twisted = with(NodeKind::Twist, {box(dvec3(3, 1, 4))});
    expectBox(nodeBounds(twisted), dvec3(-5, -1, -5), dvec3(5, 1, 5));
    Node bent = with(NodeKind::Bend, {box(dvec3(3, 4, 1))});
    expectBox(nodeBounds(bent), dvec3(-5, -5, -1), dvec3(5, 5, 1));
}

TEST(Bounds, RepetitionsCoverEveryCopy) {
    Node moved = with(NodeKind::Translate, {sphere(1)});
    moved.set("offset", dvec3(2, 0, 0));
    Node mirrored = with(NodeKind::Mirror, {moved});
    mirrored.set("axes", std::string("x"));
    expectBox(nodeBounds(mirrored), dvec3(-3, -1, -1), dvec3(3, 1, 1));
    Node repeated = with(NodeKind::Repeat, {sphere(0.5)});
    repeated.set("spacing", dvec3(2, 0, 0));
    repeated.set("counts", dvec3(3, 0, 0));
    expectBox(nodeBounds(repeated), dvec3(-7, -0.5, -0.5), dvec3(7, 0.5, 0.5));
    EXPECT_TRUE(nodeBounds(with(NodeKind::RepeatInfinite, {sphere(1)})).infinite);
    Node still = with(NodeKind::RepeatInfinite, {sphere(1)});
    still.set("period", dvec3(0.0));
    expectBox(nodeBounds(still), dvec3(-1), dvec3(1));
}

TEST(Bounds, ImplicitSurfacesUseTheirBox) {
    Node implicit = Node::make(NodeKind::Implicit);
    expectBox(nodeBounds(implicit), dvec3(-1.5), dvec3(1.5));
}

}  // namespace
}  // namespace sdfwb
