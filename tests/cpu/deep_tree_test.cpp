// The deepest tree a scene file may hold (kMaxNodeDepth levels, every kind
// that takes children along the chain) goes through every walk of the model
// and the engine on a 1 MB stack, an eighth of a thread's default: the
// compiler, bounds, visibility, validation, picking and the CPU render recurse
// at most one small frame per level, or not at all. (It passes on 256 KB in
// the plain build; 1 MB leaves AddressSanitizer's larger frames room.)

#include <gtest/gtest.h>

#include "cpu/cpu_renderer.h"
#include "cpu/pick.h"
#include "program/bounds.h"
#include "program/compile_scene.h"
#include "scene/node_kinds.h"
#include "scene/scene_json.h"
#include "scene/scene_validation.h"
#include "support/small_stack.h"

namespace sdfwb {
namespace {

using scene::Node;
using scene::NodeKind;

// A chain of kMaxNodeDepth levels through every kind that takes children, in
// turn; n-ary kinds get a small sphere beside the chain.
scene::Scene deepestChain() {
    std::vector<NodeKind> parents;
    for (int k = 0; k < scene::kNodeKindCount; ++k) {
        auto kind = static_cast<NodeKind>(k);
        if (scene::kindSpec(kind).maxChildren != 0) parents.push_back(kind);
    }
    Node node = Node::make(NodeKind::Sphere);
    for (int level = 1; level < scene::kMaxNodeDepth; ++level) {
        NodeKind kind = parents[static_cast<size_t>(level) % parents.size()];
        Node parent = Node::make(kind);
        parent.children.push_back(std::move(node));
        if (parent.children.size() < static_cast<size_t>(scene::kindSpec(kind).minChildren) ||
            scene::kindSpec(kind).maxChildren != 1) {
            Node beside = Node::make(NodeKind::Sphere);
            beside.set("radius", 0.01);
            parent.children.push_back(std::move(beside));
        }
        node = std::move(parent);
    }
    scene::Scene scene;
    scene.root = std::move(node);
    scene.render.width = 8;
    scene.render.height = 8;
    return scene;
}

TEST(DeepTree, TheDeepestLegalTreeGoesThroughEveryWalkOnASmallStack) {
    const scene::Scene scene = deepestChain();
    ASSERT_EQ(scene::treeDepth(scene.root), scene::kMaxNodeDepth);
    std::vector<std::string> problems;
    bool rendered = false;
    test::onSmallStack(1024 * 1024, [&] {
        problems = scene::validateScene(scene);
        if (!problems.empty()) return;
        scene::Scene back = scene::sceneFromJson(scene::sceneToJson(scene));
        (void)program::nodeBounds(back.root);
        program::Program program = program::compileScene(back);
        (void)cpu::primitivePaths(back.root);
        (void)cpu::primitiveAt(back, program, glm::dvec3(0.0));
        rendered = !cpu::renderCpu(program).cancelled;
    });
    EXPECT_TRUE(problems.empty()) << problems[0];
    EXPECT_TRUE(rendered);
}

}  // namespace
}  // namespace sdfwb
