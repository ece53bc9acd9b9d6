#include "scene/scene_validation.h"

#include "io/quoted_text.h"
#include "scene/json_text.h"
#include "scene/setting_checks.h"
#include "scene/settings_table.h"

namespace sdfwb::scene {

std::string FormulaVerdicts::check(const FieldSpec& field, const FieldValue& value) {
    const std::string* text = std::get_if<std::string>(&value);
    if (field.type != FieldType::Formula || !text) return checkField(field, value);
    std::string key = std::to_string(static_cast<int>(field.range)) + '\n' + *text;
    if (auto it = verdicts_.find(key); it != verdicts_.end()) return it->second;
    if (verdicts_.size() >= kMaxRemembered) verdicts_.clear();
    std::string verdict = checkField(field, value);
    verdicts_.emplace(std::move(key), verdict);
    return verdict;
}

std::vector<std::pair<std::string, std::string>> nodeStructureProblems(const KindSpec& spec, const Node& node) {
    std::vector<std::pair<std::string, std::string>> problems = checkNodeFields(spec, node.fields);
    int count = static_cast<int>(node.children.size());
    if (count < spec.minChildren || (spec.maxChildren >= 0 && count > spec.maxChildren)) {
        std::string expected = spec.minChildren == spec.maxChildren ? "exactly " + std::to_string(spec.minChildren)
                                                                    : "at least " + std::to_string(spec.minChildren);
        problems.emplace_back("children", std::string(spec.name) + " needs " + expected + " child" +
                                              (spec.minChildren == 1 && spec.maxChildren == 1 ? "" : "ren") +
                                              " (got " + std::to_string(count) + ")");
    }
    return problems;
}

std::string lightCountProblem(std::size_t count) {
    if (count <= static_cast<std::size_t>(kMaxLights)) return "";
    return "at most " + std::to_string(kMaxLights) + " lights (got " + std::to_string(count) + ")";
}

std::string materialNameProblem(const std::string& name, std::set<std::string>& seen) {
    if (name.empty()) return "a material needs a non-empty name";
    if (!seen.insert(name).second) return "duplicate material name " + io::quoted(name);
    return "";
}

std::string problemAt(const std::string& path, const std::string& reason) {
    return abbreviatedPath(path) + ": " + reason;
}

namespace {

std::string missingMaterial(const std::string& name) {
    return "no material named " + io::quoted(name) + " in materials";
}

// Walks the tree depth first on a stack of its own (trees are kMaxNodeDepth
// deep), keeping one JSON path that grows and shrinks with the walk instead
// of a path per node: this runs after every edit. enter(node, path, depth)
// says whether to go below the node; leave(node, path) runs after its children.
template <typename Enter, typename Leave>
void walkTree(const Node& root, Enter enter, Leave leave) {
    struct Frame {
        const Node* node;
        std::size_t next;        // the next child to visit
        std::size_t pathLength;  // of the node's own path
    };
    std::string path = "root";
    std::vector<Frame> stack;
    if (enter(root, path, 1)) stack.push_back({&root, 0, path.size()});
    while (!stack.empty()) {
        Frame& top = stack.back();
        path.resize(top.pathLength);
        if (top.next < top.node->children.size()) {
            const std::size_t i = top.next++;
            const Node& child = top.node->children[i];
            path += ".children[" + std::to_string(i) + "]";
            if (enter(child, path, static_cast<int>(stack.size()) + 1)) stack.push_back({&child, 0, path.size()});
            continue;
        }
        leave(*top.node, path);
        stack.pop_back();
    }
}

}  // namespace

std::vector<std::string> materialReferenceProblems(const Scene& scene) {
    std::vector<std::string> problems;
    auto enter = [&](const Node& node, const std::string& path, int) {
        const KindSpec& spec = kindSpec(node.kind);
        if (int index = fieldIndex(spec, "material"); index >= 0 && static_cast<size_t>(index) < node.fields.size()) {
            const std::string* name = std::get_if<std::string>(&node.fields[static_cast<size_t>(index)]);
            if (name && !name->empty() && !scene.findMaterial(*name)) {
                problems.push_back(problemAt(path + ".material", missingMaterial(*name)));
            }
        }
        return true;
    };
    walkTree(scene.root, enter, [](const Node&, const std::string&) {});
    const std::string& ground = scene.environment.ground.material;
    if (!ground.empty() && !scene.findMaterial(ground)) {
        problems.push_back(problemAt("environment.ground.material", missingMaterial(ground)));
    }
    return problems;
}

namespace {

class Collector {
public:
    std::vector<std::string> problems;

    void fail(const std::string& path, const std::string& reason) {
        if (!reason.empty()) problems.push_back(problemAt(path, reason));
    }

    template <typename Owner>
    void settings(std::span<const Setting<Owner>> rows, const Owner& owner, const std::string& path) {
        for (const Setting<Owner>& row : rows) {
            SettingProblem problem = settingProblem(row, owner);
            if (!problem.reason.empty()) fail(path + "." + std::string(row.key) + problem.suffix, problem.reason);
        }
    }

    void tree(const Node& root, FormulaVerdicts* verdicts) {
        auto enter = [&](const Node& node, const std::string& path, int depth) {
            if (depth > kMaxNodeDepth) {
                fail(path, "nodes nested deeper than " + std::to_string(kMaxNodeDepth) + " levels");
                return false;
            }
            const KindSpec& spec = kindSpec(node.kind);
            for (size_t i = 0; i < spec.fields.size() && i < node.fields.size(); ++i) {
                std::string reason = verdicts ? verdicts->check(spec.fields[i], node.fields[i])
                                              : checkField(spec.fields[i], node.fields[i]);
                if (!reason.empty()) fail(path + "." + std::string(spec.fields[i].name), reason);
            }
            return true;
        };
        auto leave = [&](const Node& node, const std::string& path) {
            for (const auto& [field, reason] : nodeStructureProblems(kindSpec(node.kind), node)) {
                fail(path + "." + field, reason);
            }
        };
        walkTree(root, enter, leave);
    }
};

}  // namespace

std::vector<std::string> cameraProblems(const Camera& camera) {
    Collector out;
    out.settings(cameraSettings(), camera, "camera");
    return out.problems;
}

std::vector<std::string> validateScene(const Scene& scene, FormulaVerdicts* verdicts) {
    Collector out;
    out.problems = cameraProblems(scene.camera);
    out.settings(renderSettings(), scene.render, "render");
    out.settings(environmentSettings(), scene.environment, "environment");
    out.settings(groundSettings(), scene.environment.ground, "environment.ground");
    out.fail("lights", lightCountProblem(scene.lights.size()));
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        out.settings(lightSettings(), scene.lights[i], "lights[" + std::to_string(i) + "]");
    }
    std::set<std::string> names;
    std::set<std::pair<std::string, bool>> images;  // a file read as colour and as heights is two images
    for (size_t i = 0; i < scene.materials.size(); ++i) {
        const Material& m = scene.materials[i];
        const std::string path = "materials[" + std::to_string(i) + "]";
        out.settings(materialSettings(), m, path);
        out.fail(path + ".name", materialNameProblem(m.name, names));
        auto count = [&](bool used, const std::string& file, bool heights, const char* key) {
            if (!used) return;
            images.insert({file, heights});
            if (images.size() == static_cast<size_t>(kMaxTextureImages) + 1) {
                out.fail(path + "." + key, "a scene may use at most " + std::to_string(kMaxTextureImages) +
                                               " texture and bump images");
            }
        };
        count(m.texture == TexturePattern::Image, m.textureImage, false, "texture_image");
        count(m.bump == BumpPattern::Image, m.bumpImage, true, "bump_image");
    }
    out.tree(scene.root, verdicts);
    for (std::string& problem : materialReferenceProblems(scene)) out.problems.push_back(std::move(problem));
    return out.problems;
}

}  // namespace sdfwb::scene
