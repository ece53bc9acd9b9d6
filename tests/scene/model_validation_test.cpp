// The model validator (scene/scene_validation.h) against the JSON reader: for
// every scene of scenes/ and for invalid values put into each setting and node
// field, both report the same problems. A rule that only one of them applies
// fails here.
#include <algorithm>
#include <filesystem>

#include <gtest/gtest.h>

#include "scene/scene_json.h"
#include "scene/scene_validation.h"
#include "scene/settings_table.h"
#include "support/source_tree.h"

namespace sdfwb::scene {
namespace {

std::vector<std::string> sorted(std::vector<std::string> v) {
    std::sort(v.begin(), v.end());
    return v;
}

std::vector<std::string> readerProblems(const Scene& scene) {
    try {
        sceneFromJson(sceneToJson(scene));
    } catch (const SceneError& error) {
        return error.problems();
    }
    return {};
}

void expectSameProblems(const Scene& scene, const std::string& what) {
    EXPECT_EQ(sorted(validateScene(scene)), sorted(readerProblems(scene))) << what;
}

std::vector<Scene> projectScenes() {
    std::vector<Scene> scenes;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(test::sourceDir() + "/scenes")) {
        if (entry.path().extension() == ".json") scenes.push_back(loadSceneFile(entry.path()));
    }
    return scenes;
}

// Values at and past every edge of a row's range; some are valid, most not.
template <typename Owner>
std::vector<Owner> edgeValues(const Setting<Owner>& row, const Owner& owner) {
    std::vector<Owner> out;
    auto with = [&](auto set) {
        Owner o = owner;
        set(o);
        out.push_back(o);
    };
    switch (row.type) {
    case SettingType::Integer:
        for (double v : {row.minimum - 1, row.minimum, row.maximum, row.maximum + 1}) {
            with([&](Owner& o) { o.*std::get<int Owner::*>(row.member) = static_cast<int>(v); });
        }
        break;
    case SettingType::Real:
        for (double v : {-1.0, 0.0, row.minimum, row.maximum, row.maximum + 1, 1e300}) {
            with([&](Owner& o) { o.*std::get<double Owner::*>(row.member) = v; });
        }
        break;
    case SettingType::Colour:
    case SettingType::Vector:
    case SettingType::Direction:
        for (glm::dvec3 v : {glm::dvec3(0.0), glm::dvec3(-1, 0, 0), glm::dvec3(1e300)}) {
            with([&](Owner& o) { o.*std::get<glm::dvec3 Owner::*>(row.member) = v; });
        }
        break;
    case SettingType::Choice:
    case SettingType::Flag:
    case SettingType::Text:
    case SettingType::ImageFile: break;
    }
    return out;
}

template <typename Owner, typename Access>
void sweepSettings(Scene scene, std::span<const Setting<Owner>> rows, Access access, const std::string& where) {
    for (const Setting<Owner>& row : rows) {
        for (const Owner& value : edgeValues(row, access(scene))) {
            Scene edited = scene;
            access(edited) = value;
            expectSameProblems(edited, where + "." + std::string(row.key));
        }
    }
}

TEST(ModelValidation, EveryProjectSceneIsValid) {
    std::vector<Scene> scenes = projectScenes();
    ASSERT_GT(scenes.size(), 40u);
    for (const Scene& scene : scenes) EXPECT_TRUE(validateScene(scene).empty()) << scene.name;
}

TEST(ModelValidation, SettingsAgreeWithTheReader) {
    Scene scene = loadSceneFile(test::sourceDir() + "/scenes/default.json");
    scene.materials.push_back(defaultMaterial());
    scene.materials.back().name = "extra";
    sweepSettings(scene, cameraSettings(), [](Scene& s) -> Camera& { return s.camera; }, "camera");
    sweepSettings(scene, renderSettings(), [](Scene& s) -> RenderSettings& { return s.render; }, "render");
    sweepSettings(scene, environmentSettings(), [](Scene& s) -> Environment& { return s.environment; }, "environment");
    sweepSettings(scene, groundSettings(), [](Scene& s) -> Ground& { return s.environment.ground; }, "ground");
    sweepSettings(scene, lightSettings(), [](Scene& s) -> Light& { return s.lights.front(); }, "lights[0]");
    sweepSettings(scene, materialSettings(), [](Scene& s) -> Material& { return s.materials.back(); }, "materials");
}

TEST(ModelValidation, ListsAndReferencesAgreeWithTheReader) {
    Scene scene = loadSceneFile(test::sourceDir() + "/scenes/default.json");
    Scene lights = scene;
    lights.lights.assign(kMaxLights + 1, Light{});
    expectSameProblems(lights, "too many lights");
    Scene duplicate = scene;
    duplicate.materials.push_back(duplicate.materials.front());
    expectSameProblems(duplicate, "duplicate material");
    Scene unnamed = scene;
    unnamed.materials.push_back(defaultMaterial());
    unnamed.materials.back().name.clear();
    expectSameProblems(unnamed, "unnamed material");
    Scene ground = scene;
    ground.environment.ground.material = "nowhere";
    expectSameProblems(ground, "ground material");
    ASSERT_FALSE(validateScene(ground).empty());
}

// The nodes of a tree, each once, in a fixed order.
std::vector<Node*> flatten(Node& root) {
    std::vector<Node*> nodes, stack{&root};
    while (!stack.empty()) {
        Node* n = stack.back();
        stack.pop_back();
        nodes.push_back(n);
        for (Node& c : n->children) stack.push_back(&c);
    }
    return nodes;
}

// Every node of every project scene with each real field made negative and
// then huge, each material pointing nowhere, and its children taken away.
TEST(ModelValidation, NodeFieldsAndChildrenAgreeWithTheReader) {
    int edits = 0;
    for (const Scene& scene : projectScenes()) {
        Scene base = scene;
        const std::vector<Node*> nodes = flatten(base.root);
        for (size_t k = 0; k < nodes.size() && k < 12; ++k) {
            const size_t index = k;
            auto editNode = [&](auto change, const std::string& what) {
                Scene edited = base;
                change(*flatten(edited.root)[index]);
                expectSameProblems(edited, scene.name + " node " + std::to_string(index) + " " + what);
                ++edits;
            };
            const KindSpec& spec = kindSpec(nodes[k]->kind);
            for (size_t f = 0; f < spec.fields.size(); ++f) {
                if (spec.fields[f].type == FieldType::Real) {
                    for (double v : {-1.0, 0.0, 1e300}) {
                        editNode([&](Node& n) { n.fields[f] = v; }, std::string(spec.fields[f].name));
                    }
                } else if (spec.fields[f].type == FieldType::Vec3) {
                    editNode([&](Node& n) { n.fields[f] = glm::dvec3(0.0); }, std::string(spec.fields[f].name));
                } else if (spec.fields[f].type == FieldType::Material) {
                    editNode([&](Node& n) { n.fields[f] = std::string("nowhere"); }, "material");
                } else if (spec.fields[f].type == FieldType::Formula) {
                    editNode([&](Node& n) { n.fields[f] = std::string("x +* 1"); }, "formula");
                }
            }
            editNode([](Node& n) { n.children.clear(); }, "children");
        }
    }
    EXPECT_GT(edits, 500);
}

TEST(ModelValidation, ValuesJsonCannotHoldAreProblemsToo) {
    Scene scene;
    scene.camera.fov = std::nan("");
    scene.camera.target.y = std::numeric_limits<double>::infinity();
    EXPECT_EQ(validateScene(scene),
              (std::vector<std::string>{"camera.target[1]: must be a finite number", "camera.fov: must be a finite number"}));
}

TEST(ModelValidation, TreesDeeperThanTheLimitAreReportedWhereTheyPassIt) {
    Scene scene;
    Node* at = &scene.root;
    for (int level = 1; level <= kMaxNodeDepth; ++level) {
        at->children.push_back(Node::make(NodeKind::Translate));
        at = &at->children.back();
    }
    at->children.push_back(Node::make(NodeKind::Sphere));
    std::vector<std::string> problems = validateScene(scene);
    ASSERT_FALSE(problems.empty());
    EXPECT_NE(problems.front().find("nodes nested deeper than 1024 levels"), std::string::npos) << problems.front();
}

}  // namespace
}  // namespace sdfwb::scene
