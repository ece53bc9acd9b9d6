#pragma once
// Large scenes for the pruning tests and benchmarks, generated rather than
// committed: the molecule (tests/data/large, MIT, see its README) and its
// hard-union variant, a city of boxes under a hard union, a smooth-blended
// chain of capsules, and nested transformed groups (unions of smooth unions,
// rotated and scaled groups, differences).

#include <cmath>
#include <string>

#include "scene/scene.h"
#include "scene/scene_json.h"
#include "support/source_tree.h"

namespace sdfwb::test {

inline scene::Scene moleculeScene(const std::string& name) {
    return scene::loadSceneFile(sdfwb::test::sourceDir() + "/tests/data/large/" + name + ".json");
}

// The same spheres under a hard union.
inline scene::Scene hardVariant(scene::Scene s) {
    scene::Node root = scene::Node::make(scene::NodeKind::Union);
    root.children = std::move(s.root.children);
    s.root = std::move(root);
    return s;
}

inline scene::Node translated(glm::dvec3 offset, scene::Node child) {
    scene::Node t = scene::Node::make(scene::NodeKind::Translate);
    t.set("offset", offset);
    t.children.push_back(std::move(child));
    return t;
}

// A pseudo-random number in [0, 1) from an index (no global state).
inline double hashUnit(int i) {
    double x = std::sin(static_cast<double>(i) * 12.9898 + 78.233) * 43758.5453;
    return x - std::floor(x);
}

inline scene::Scene baseScene() {
    scene::Scene s;
    s.camera.target = glm::dvec3(0.0);
    s.camera.distance = 3.2;
    s.render.width = 240;
    s.render.height = 135;
    s.render.maxDistance = 20;
    s.render.aoSamples = 4;
    s.render.aoDistance = 0.2;
    return s;
}

// `count` boxes on a square lot of side 2, heights varying, under a hard union.
inline scene::Scene cityScene(int count) {
    scene::Scene s = baseScene();
    int side = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(count))));
    double pitch = 2.0 / side;
    for (int i = 0; i < count; ++i) {
        double h = 0.05 + 0.3 * hashUnit(i);
        scene::Node box = scene::Node::make(scene::NodeKind::Box);
        box.set("half_extents", glm::dvec3(0.35 * pitch, h, 0.35 * pitch));
        glm::dvec3 at(-1.0 + pitch * (i % side + 0.5), h - 0.3, -1.0 + pitch * (i / side + 0.5));
        s.root.children.push_back(translated(at, box));
    }
    return s;
}

// `count` capsules end to end along a helix, smoothly blended (k = 0.02).
inline scene::Scene capsuleChainScene(int count) {
    scene::Scene s = baseScene();
    s.root = scene::Node::make(scene::NodeKind::SmoothUnion);
    s.root.set("k", 0.02);
    auto at = [&](int i) {
        double t = 12.0 * M_PI * i / count;
        return glm::dvec3(0.8 * std::cos(t), -0.6 + 1.2 * i / count, 0.8 * std::sin(t));
    };
    for (int i = 0; i < count; ++i) {
        scene::Node capsule = scene::Node::make(scene::NodeKind::Capsule);
        capsule.set("a", at(i));
        capsule.set("b", at(i + 1));
        capsule.set("radius", 0.012);
        s.root.children.push_back(capsule);
    }
    return s;
}

// Groups of `perGroup` spheres: each group a smooth union, rotated and scaled,
// with a box taken out of every other group, all under a hard union.
inline scene::Scene nestedGroupsScene(int groups, int perGroup) {
    scene::Scene s = baseScene();
    for (int g = 0; g < groups; ++g) {
        scene::Node blob = scene::Node::make(scene::NodeKind::SmoothUnion);
        blob.set("k", 0.03);
        for (int i = 0; i < perGroup; ++i) {
            int n = g * perGroup + i;
            scene::Node sphere = scene::Node::make(scene::NodeKind::Sphere);
            sphere.set("radius", 0.03 + 0.02 * hashUnit(3 * n));
            glm::dvec3 at(0.3 * (hashUnit(3 * n + 1) - 0.5), 0.3 * (hashUnit(3 * n + 2) - 0.5), 0.1 * hashUnit(n));
            blob.children.push_back(translated(at, sphere));
        }
        scene::Node group = blob;
        if (g % 2 == 1) {
            scene::Node cut = scene::Node::make(scene::NodeKind::Difference);
            scene::Node box = scene::Node::make(scene::NodeKind::Box);
            box.set("half_extents", glm::dvec3(0.06));
            cut.children = {blob, box};
            group = cut;
        }
        scene::Node scale = scene::Node::make(scene::NodeKind::Scale);
        scale.set("factor", 0.8 + 0.4 * hashUnit(7 * g));
        scale.children.push_back(group);
        scene::Node rotate = scene::Node::make(scene::NodeKind::Rotate);
        rotate.set("angles", glm::dvec3(90.0 * hashUnit(5 * g), 90.0 * hashUnit(5 * g + 1), 0.0));
        rotate.children.push_back(scale);
        int side = static_cast<int>(std::ceil(std::cbrt(static_cast<double>(groups))));
        glm::dvec3 cell(g % side, (g / side) % side, g / (side * side));
        s.root.children.push_back(translated((cell + 0.5) * (2.0 / side) - glm::dvec3(1.0), rotate));
    }
    return s;
}

}  // namespace sdfwb::test
