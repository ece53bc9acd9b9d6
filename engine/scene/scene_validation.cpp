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

namespace {

std::string missingMaterial(const std::string& name) {
    return "no material named " + io::quoted(name) + " in materials";
}

// A node of the walk with its JSON path; `leaving` marks the second visit,
// after its children, where the checks that need them run (the reader's order).
struct Visit {
    const Node* node;
    std::string path;
    int depth;
    bool leaving;
};

}  // namespace

std::vector<std::string> materialReferenceProblems(const Scene& scene) {
    std::vector<std::string> problems;
    std::vector<std::pair<const Node*, std::string>> stack{{&scene.root, "root"}};
    while (!stack.empty()) {
        auto [node, path] = std::move(stack.back());
        stack.pop_back();
        const KindSpec& spec = kindSpec(node->kind);
        if (int index = fieldIndex(spec, "material"); index >= 0 && static_cast<size_t>(index) < node->fields.size()) {
            const std::string* name = std::get_if<std::string>(&node->fields[static_cast<size_t>(index)]);
            if (name && !name->empty() && !scene.findMaterial(*name)) {
                problems.push_back(abbreviatedPath(path + ".material") + ": " + missingMaterial(*name));
            }
        }
        for (size_t i = node->children.size(); i-- > 0;) {  // reversed: the first child is checked first
            stack.emplace_back(&node->children[i], path + ".children[" + std::to_string(i) + "]");
        }
    }
    const std::string& ground = scene.environment.ground.material;
    if (!ground.empty() && !scene.findMaterial(ground)) {
        problems.push_back("environment.ground.material: " + missingMaterial(ground));
    }
    return problems;
}

namespace {

class Collector {
public:
    std::vector<std::string> problems;

    void fail(const std::string& path, const std::string& reason) {
        if (!reason.empty()) problems.push_back(abbreviatedPath(path) + ": " + reason);
    }

    template <typename Owner>
    void settings(std::span<const Setting<Owner>> rows, const Owner& owner, const std::string& path) {
        for (const Setting<Owner>& row : rows) {
            SettingProblem problem = settingProblem(row, owner);
            fail(path + "." + std::string(row.key) + problem.suffix, problem.reason);
        }
    }

    void tree(const Node& root, FormulaVerdicts* verdicts) {
        std::vector<Visit> stack{{&root, "root", 1, false}};
        while (!stack.empty()) {
            Visit visit = std::move(stack.back());
            stack.pop_back();
            const Node& node = *visit.node;
            const KindSpec& spec = kindSpec(node.kind);
            if (visit.leaving) {
                for (const auto& [field, reason] : nodeStructureProblems(spec, node)) fail(visit.path + "." + field, reason);
                continue;
            }
            if (visit.depth > kMaxNodeDepth) {
                fail(visit.path, "nodes nested deeper than " + std::to_string(kMaxNodeDepth) + " levels");
                continue;
            }
            for (size_t i = 0; i < spec.fields.size() && i < node.fields.size(); ++i) {
                std::string reason = verdicts ? verdicts->check(spec.fields[i], node.fields[i])
                                              : checkField(spec.fields[i], node.fields[i]);
                fail(visit.path + "." + std::string(spec.fields[i].name), reason);
            }
            stack.push_back({visit.node, visit.path, visit.depth, true});
            for (size_t i = node.children.size(); i-- > 0;) {
                stack.push_back({&node.children[i], visit.path + ".children[" + std::to_string(i) + "]",
                                 visit.depth + 1, false});
            }
        }
    }
};

}  // namespace

std::vector<std::string> validateScene(const Scene& scene, FormulaVerdicts* verdicts) {
    Collector out;
    out.settings(cameraSettings(), scene.camera, "camera");
    out.settings(renderSettings(), scene.render, "render");
    out.settings(environmentSettings(), scene.environment, "environment");
    out.settings(groundSettings(), scene.environment.ground, "environment.ground");
    out.fail("lights", lightCountProblem(scene.lights.size()));
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        out.settings(lightSettings(), scene.lights[i], "lights[" + std::to_string(i) + "]");
    }
    std::set<std::string> names;
    for (size_t i = 0; i < scene.materials.size(); ++i) {
        const std::string path = "materials[" + std::to_string(i) + "]";
        out.settings(materialSettings(), scene.materials[i], path);
        out.fail(path + ".name", materialNameProblem(scene.materials[i].name, names));
    }
    out.tree(scene.root, verdicts);
    for (std::string& problem : materialReferenceProblems(scene)) out.problems.push_back(std::move(problem));
    return out.problems;
}

}  // namespace sdfwb::scene
