#include "scene/scene_json.h"

#include <cmath>
#include <optional>
#include <set>
#include <span>
#include <type_traits>

#include "io/atomic_file.h"
#include "io/quoted_text.h"
#include "scene/json_text.h"
#include "scene/scene_validation.h"
#include "scene/setting_checks.h"
#include "scene/settings_table.h"

namespace sdfwb::scene {

using json = nlohmann::ordered_json;
using glm::dvec3;

SceneError::SceneError(std::vector<std::string> problems)
    : std::runtime_error(problems.empty() ? "invalid scene" : problems.front()), problems_(std::move(problems)) {}

namespace {

// Collects problems while reading; each reader call takes the JSON path of its value.
class Reader {
public:
    std::vector<std::string> problems;

    void fail(const std::string& path, const std::string& reason) {
        problems.push_back(problemAt(path, reason));
    }

    bool number(const json& value, const std::string& path, double& out) {
        if (!value.is_number()) {
            fail(path, "must be a number");
            return false;
        }
        double v = value.get<double>();
        if (!std::isfinite(v)) {
            fail(path, "must be a finite number");
            return false;
        }
        out = v;
        return true;
    }

    bool vec3(const json& value, const std::string& path, dvec3& out) {
        if (!value.is_array() || value.size() != 3) {
            fail(path, "must be an array of 3 numbers");
            return false;
        }
        dvec3 v;
        for (int i = 0; i < 3; ++i) {
            if (!number(value[static_cast<size_t>(i)], path + "[" + std::to_string(i) + "]", v[i])) {
                return false;
            }
        }
        out = v;
        return true;
    }

    void flag(const json& value, const std::string& path, bool& out) {
        if (!value.is_boolean()) {
            fail(path, "must be true or false");
            return;
        }
        out = value.get<bool>();
    }

    void string(const json& value, const std::string& path, std::string& out) {
        if (!value.is_string()) {
            fail(path, "must be a string");
            return;
        }
        out = value.get<std::string>();
    }

    bool choice(const json& value, const std::string& path, std::span<const char* const> names, int& out) {
        if (!value.is_string()) {
            fail(path, "must be a string");
            return false;
        }
        std::string s = value.get<std::string>();
        std::string list;
        for (size_t i = 0; i < names.size(); ++i) {
            if (names[i] == s) {
                out = static_cast<int>(i);
                return true;
            }
            list += (i ? ", " : "") + std::string(names[i]);
        }
        fail(path, "must be one of " + list + " (got " + io::quoted(s) + ")");
        return false;
    }
};

// Reads the members of one JSON object, then reports members nobody asked for.
class ObjectReader {
public:
    ObjectReader(Reader& reader, const json& object, std::string path)
        : reader_(reader), object_(object), path_(std::move(path)) {
        valid_ = object.is_object();
        if (!valid_) {
            reader_.fail(path_, "must be an object");
        }
    }

    bool valid() const { return valid_; }
    std::string pathOf(std::string_view key) const { return path_.empty() ? std::string(key) : path_ + "." + std::string(key); }

    // Calls read(value, path) if the member exists.
    template <typename ReadFn>
    void member(std::string_view key, ReadFn read) {
        known_.insert(std::string(key));
        if (!valid_) {
            return;
        }
        auto it = object_.find(std::string(key));
        if (it != object_.end()) {
            read(*it, pathOf(key));
        }
    }

    void finish(std::string_view what) {
        if (!valid_) {
            return;
        }
        for (auto it = object_.begin(); it != object_.end(); ++it) {
            if (!known_.contains(it.key())) {
                std::string list;
                for (const std::string& k : orderedKnown()) {
                    list += (list.empty() ? "" : ", ") + k;
                }
                reader_.fail(pathOf(io::escapedExcerpt(it.key())), "unknown field (" + std::string(what) + " has: " + list + ")");
            }
        }
    }

private:
    std::vector<std::string> orderedKnown() const { return {known_.begin(), known_.end()}; }

    Reader& reader_;
    const json& object_;
    std::string path_;
    std::set<std::string> known_;
    bool valid_ = false;
};

// ---- settings from the tables of scene/settings_table.h ----
template <typename Owner>
void readSetting(Reader& reader, const Setting<Owner>& row, const json& value, const std::string& path, Owner& owner) {
    // Reads the value's type here and applies the row's rule (scene/setting_checks.h) to what was read.
    auto checked = [&](const std::string& reason) {
        if (!reason.empty()) reader.fail(path, reason);
        return reason.empty();
    };
    switch (row.type) {
    case SettingType::Integer: {
        double v = 0;
        if (reader.number(value, path, v) && checked(integerProblem(row, v))) {
            owner.*std::get<int Owner::*>(row.member) = static_cast<int>(v);
        }
        return;
    }
    case SettingType::Real: {
        double v = 0;
        if (reader.number(value, path, v) && checked(realProblem(row, v))) owner.*std::get<double Owner::*>(row.member) = v;
        return;
    }
    case SettingType::Choice: {
        const ChoiceMember<Owner>& access = std::get<ChoiceMember<Owner>>(row.member);
        int index = 0;
        if (reader.choice(value, path, row.choices, index)) access.set(owner, index);
        return;
    }
    case SettingType::Colour:
    case SettingType::Vector:
    case SettingType::Direction: {
        dvec3 v;
        if (!reader.vec3(value, path, v)) return;
        std::string reason = row.type == SettingType::Colour      ? colourProblem(v)
                             : row.type == SettingType::Direction ? directionProblem(v)
                                                                  : "";
        if (checked(reason)) owner.*std::get<dvec3 Owner::*>(row.member) = v;
        return;
    }
    case SettingType::Flag: reader.flag(value, path, owner.*std::get<bool Owner::*>(row.member)); return;
    case SettingType::Text:
    case SettingType::ImageFile: reader.string(value, path, owner.*std::get<std::string Owner::*>(row.member)); return;
    }
}

template <typename Owner>
void readSettings(Reader& reader, ObjectReader& object, std::span<const Setting<Owner>> rows, Owner& owner) {
    for (const Setting<Owner>& row : rows) {
        object.member(row.key, [&](const json& v, const std::string& p) { readSetting(reader, row, v, p, owner); });
    }
}

json vec3Json(const dvec3& v) { return json::array({v.x, v.y, v.z}); }

template <typename Owner>
json settingsJson(std::span<const Setting<Owner>> rows, const Owner& owner) {
    json out = json::object();
    for (const Setting<Owner>& row : rows) {
        json& slot = out[std::string(row.key)];
        std::visit(
            [&](const auto& member) {
                using Member = std::decay_t<decltype(member)>;
                if constexpr (std::is_same_v<Member, ChoiceMember<Owner>>) {
                    slot = row.choices[static_cast<size_t>(member.get(owner))];
                } else if constexpr (std::is_same_v<Member, dvec3 Owner::*>) {
                    slot = vec3Json(owner.*member);
                } else {
                    slot = owner.*member;
                }
            },
            row.member);
    }
    return out;
}

FieldValue readFieldValue(Reader& reader, const FieldSpec& field, const json& value, const std::string& path) {
    FieldValue result = field.defaultValue;
    switch (field.type) {
    case FieldType::Real: {
        double v = 0;
        if (reader.number(value, path, v)) {
            result = v;
        }
        break;
    }
    case FieldType::Vec3: {
        dvec3 v;
        if (reader.vec3(value, path, v)) {
            result = v;
        }
        break;
    }
    case FieldType::Choice:
    case FieldType::Material:
    case FieldType::Formula: {
        std::string s;
        if (!value.is_string()) {
            reader.fail(path, "must be a string");
            return result;
        }
        result = value.get<std::string>();
        break;
    }
    }
    std::string problem = checkField(field, result);
    if (!problem.empty()) {
        reader.fail(path, problem);
        return field.defaultValue;
    }
    return result;
}

// A node being read: its own members are read on the way down, its children
// one at a time, and the checks that need the children on the way up.
struct PendingNode {
    Node node;
    const KindSpec* spec;
    ObjectReader object;
    std::string path;
    const json* children = nullptr;  // the "children" member, when it is an array
    std::string childrenPath{};
    std::size_t next = 0;  // the next child to read
};

// Reads a node's own members at level `depth` (the root being 1). Without a
// PendingNode the node failed (the problem is recorded) and stands as an empty
// Node, so that its parent's checks still run.
std::optional<PendingNode> beginNode(Reader& reader, const json& value, const std::string& path, int depth) {
    if (depth > kMaxNodeDepth) {
        reader.fail(path, "nodes nested deeper than " + std::to_string(kMaxNodeDepth) + " levels");
        return std::nullopt;
    }
    if (!value.is_object()) {
        reader.fail(path, "must be an object");
        return std::nullopt;
    }
    auto kindIt = value.find("kind");
    if (kindIt == value.end() || !kindIt->is_string()) {
        reader.fail(path + ".kind", "missing node kind (a string such as \"sphere\" or \"union\")");
        return std::nullopt;
    }
    const KindSpec* spec = findKind(kindIt->get<std::string>());
    if (!spec) {
        std::string list;
        for (const KindSpec& k : allKinds()) {
            list += (list.empty() ? "" : ", ") + std::string(k.name);
        }
        reader.fail(path + ".kind", "unknown node kind " + io::quoted(kindIt->get<std::string>()) + " (known: " + list + ")");
        return std::nullopt;
    }
    PendingNode pending{Node::make(spec->kind), spec, ObjectReader(reader, value, path), path};
    Node& node = pending.node;
    ObjectReader& object = pending.object;
    object.member("kind", [](const json&, const std::string&) {});
    object.member("name", [&](const json& v, const std::string& p) { reader.string(v, p, node.name); });
    object.member("hidden", [&](const json& v, const std::string& p) { reader.flag(v, p, node.hidden); });
    object.member("solo", [&](const json& v, const std::string& p) { reader.flag(v, p, node.solo); });
    for (size_t i = 0; i < spec->fields.size(); ++i) {
        const FieldSpec& field = spec->fields[i];
        object.member(field.name, [&](const json& v, const std::string& p) {
            node.fields[i] = readFieldValue(reader, field, v, p);
        });
    }
    if (spec->maxChildren != 0) {
        object.member("children", [&](const json& v, const std::string& p) {
            if (!v.is_array()) {
                reader.fail(p, "must be an array of nodes");
                return;
            }
            pending.children = &v;
            pending.childrenPath = p;
        });
    }
    return pending;
}

// The checks of a node whose children have all been read.
Node finishNode(Reader& reader, PendingNode& pending) {
    const KindSpec& spec = *pending.spec;
    pending.object.finish(spec.name);
    for (const auto& [field, reason] : nodeStructureProblems(spec, pending.node)) {
        reader.fail(pending.path + "." + field, reason);
    }
    return std::move(pending.node);
}

// Reads a node tree depth first on a stack of its own, not the native one: a
// legal tree is kMaxNodeDepth levels deep, and a thread's stack (smaller
// still under AddressSanitizer) need not hold a frame per level. Problems come
// in the order a recursive reader would give them.
Node readNode(Reader& reader, const json& value, const std::string& path) {
    std::vector<PendingNode> stack;
    std::optional<PendingNode> root = beginNode(reader, value, path, 1);
    if (!root) {
        return Node{};
    }
    stack.push_back(std::move(*root));
    while (true) {
        PendingNode& top = stack.back();
        if (top.children && top.next < top.children->size()) {
            const std::size_t i = top.next++;
            std::optional<PendingNode> child = beginNode(reader, (*top.children)[i], top.childrenPath + "[" +
                                                         std::to_string(i) + "]", static_cast<int>(stack.size()) + 1);
            if (child) {
                stack.push_back(std::move(*child));  // `top` is invalid from here
            } else {
                top.node.children.push_back(Node{});
            }
            continue;
        }
        Node finished = finishNode(reader, top);
        stack.pop_back();
        if (stack.empty()) {
            return finished;
        }
        stack.back().node.children.push_back(std::move(finished));
    }
}

void readCamera(Reader& reader, const json& value, const std::string& path, Camera& camera) {
    ObjectReader object(reader, value, path);
    readSettings(reader, object, cameraSettings(), camera);
    object.finish("camera");
}

void readRender(Reader& reader, const json& value, const std::string& path, RenderSettings& render) {
    ObjectReader object(reader, value, path);
    readSettings(reader, object, renderSettings(), render);
    object.finish("render");
}

void readGround(Reader& reader, const json& value, const std::string& path, Ground& ground) {
    ObjectReader object(reader, value, path);
    readSettings(reader, object, groundSettings(), ground);
    object.finish("ground");
}

void readEnvironment(Reader& reader, const json& value, const std::string& path, Environment& environment) {
    ObjectReader object(reader, value, path);
    readSettings(reader, object, environmentSettings(), environment);
    object.member("ground", [&](const json& v, const std::string& p) { readGround(reader, v, p, environment.ground); });
    object.finish("environment");
}

Light readLight(Reader& reader, const json& value, const std::string& path) {
    Light light;
    ObjectReader object(reader, value, path);
    readSettings(reader, object, lightSettings(), light);
    object.finish("light");
    return light;
}

Material readMaterial(Reader& reader, const json& value, const std::string& path) {
    Material material;
    ObjectReader object(reader, value, path);
    readSettings(reader, object, materialSettings(), material);
    object.finish("material");
    return material;
}

// Versions newer than this build cannot be read; older ones are migrated step by
// step (version 1 is the first, so there are no steps yet).
void checkVersion(Reader& reader, const json& value) {
    auto format = value.find("format");
    if (format == value.end() || !format->is_string() || format->get<std::string>() != kFormatTag) {
        reader.fail("format", "must be \"" + std::string(kFormatTag) + "\"");
    }
    auto version = value.find("version");
    if (version == value.end() || !version->is_number_integer()) {
        reader.fail("version", "must be a whole number (this build reads version " + std::to_string(kFormatVersion) + ")");
        return;
    }
    // Read at the width the JSON holds it: 4294967297 must not pass as 1.
    std::string number = version->dump();
    bool supported = version->is_number_unsigned() ? version->get<std::uint64_t>() >= 1 &&
                                                        version->get<std::uint64_t>() <= kFormatVersion
                                                  : version->get<std::int64_t>() >= 1 &&
                                                        version->get<std::int64_t>() <= kFormatVersion;
    if (!supported) {
        reader.fail("version", "unsupported version " + number + " (this build reads versions 1 to " +
                                   std::to_string(kFormatVersion) + ")");
    }
}

}  // namespace

Node nodeFromJson(const json& value, const std::string& path) {
    Reader reader;
    Node node = readNode(reader, value, path);
    if (!reader.problems.empty()) {
        throw SceneError(reader.problems);
    }
    return node;
}

Scene sceneFromJson(const json& value) {
    Reader reader;
    Scene scene;
    if (!value.is_object()) {
        throw SceneError({"(top level): a scene must be a JSON object"});
    }
    checkVersion(reader, value);
    ObjectReader object(reader, value, "");
    object.member("format", [](const json&, const std::string&) {});
    object.member("version", [](const json&, const std::string&) {});
    object.member("name", [&](const json& v, const std::string& p) { reader.string(v, p, scene.name); });
    object.member("description", [&](const json& v, const std::string& p) { reader.string(v, p, scene.description); });
    object.member("camera", [&](const json& v, const std::string& p) { readCamera(reader, v, p, scene.camera); });
    object.member("render", [&](const json& v, const std::string& p) { readRender(reader, v, p, scene.render); });
    object.member("environment", [&](const json& v, const std::string& p) {
        readEnvironment(reader, v, p, scene.environment);
    });
    object.member("lights", [&](const json& v, const std::string& p) {
        if (!v.is_array()) {
            reader.fail(p, "must be an array of lights");
            return;
        }
        if (std::string reason = lightCountProblem(v.size()); !reason.empty()) reader.fail(p, reason);
        scene.lights.clear();
        for (size_t i = 0; i < v.size(); ++i) {
            scene.lights.push_back(readLight(reader, v[i], p + "[" + std::to_string(i) + "]"));
        }
    });
    object.member("materials", [&](const json& v, const std::string& p) {
        if (!v.is_array()) {
            reader.fail(p, "must be an array of materials");
            return;
        }
        std::set<std::string> names;
        for (size_t i = 0; i < v.size(); ++i) {
            std::string itemPath = p + "[" + std::to_string(i) + "]";
            Material m = readMaterial(reader, v[i], itemPath);
            if (v[i].is_object()) {
                if (std::string reason = materialNameProblem(m.name, names); !reason.empty()) {
                    reader.fail(itemPath + ".name", reason);
                }
            }
            scene.materials.push_back(std::move(m));
        }
    });
    object.member("root", [&](const json& v, const std::string& p) { scene.root = readNode(reader, v, p); });
    object.finish("a scene");
    for (std::string& problem : materialReferenceProblems(scene)) reader.problems.push_back(std::move(problem));
    if (!reader.problems.empty()) {
        throw SceneError(reader.problems);
    }
    return scene;
}

Scene parseScene(std::string_view text) {
    json value;
    try {
        value = parseStrictJson(text);
    } catch (const JsonTextError& error) {
        throw SceneError({error.what()});
    }
    return sceneFromJson(value);
}

Scene loadSceneFile(const std::filesystem::path& path) {
    std::string text;
    try {
        text = io::readTextFile(path, kMaxSceneFileBytes);
    } catch (const std::exception& error) {
        throw SceneError({error.what()});
    }
    try {
        Scene scene = parseScene(text);
        scene.directory.path = std::filesystem::absolute(path).parent_path().string();
        return scene;
    } catch (const SceneError& error) {
        std::vector<std::string> problems;
        for (const std::string& problem : error.problems()) {
            problems.push_back(path.string() + ": " + problem);
        }
        throw SceneError(problems);
    }
}

json nodeToJson(const Node& node) {
    const KindSpec& spec = kindSpec(node.kind);
    json out;
    out["kind"] = spec.name;
    if (!node.name.empty()) {
        out["name"] = node.name;
    }
    if (node.hidden) out["hidden"] = true;
    if (node.solo) out["solo"] = true;
    for (size_t i = 0; i < spec.fields.size(); ++i) {
        const FieldValue& value = node.fields[i];
        if (const double* d = std::get_if<double>(&value)) {
            out[std::string(spec.fields[i].name)] = *d;
        } else if (const dvec3* v = std::get_if<dvec3>(&value)) {
            out[std::string(spec.fields[i].name)] = vec3Json(*v);
        } else {
            out[std::string(spec.fields[i].name)] = std::get<std::string>(value);
        }
    }
    if (spec.maxChildren != 0) {
        json children = json::array();
        for (const Node& child : node.children) {
            children.push_back(nodeToJson(child));
        }
        out["children"] = std::move(children);
    }
    return out;
}

json sceneToJson(const Scene& scene) {
    json out;
    out["format"] = kFormatTag;
    out["version"] = kFormatVersion;
    out["name"] = scene.name;
    out["description"] = scene.description;
    out["camera"] = settingsJson(cameraSettings(), scene.camera);
    out["render"] = settingsJson(renderSettings(), scene.render);
    json environment = settingsJson(environmentSettings(), scene.environment);
    environment["ground"] = settingsJson(groundSettings(), scene.environment.ground);
    out["environment"] = std::move(environment);
    json lights = json::array();
    for (const Light& l : scene.lights) {
        lights.push_back(settingsJson(lightSettings(), l));
    }
    out["lights"] = std::move(lights);
    json materials = json::array();
    for (const Material& m : scene.materials) {
        materials.push_back(settingsJson(materialSettings(), m));
    }
    out["materials"] = std::move(materials);
    out["root"] = nodeToJson(scene.root);
    return out;
}

std::string serializeScene(const Scene& scene) { return sceneToJson(scene).dump(2) + "\n"; }

void saveSceneFile(const Scene& scene, const std::filesystem::path& path) {
    // A file that could not be loaded again would lose the work it holds.
    if (int depth = treeDepth(scene.root); depth > kMaxNodeDepth) {
        throw std::runtime_error("cannot write " + path.string() + ": the node tree is " + std::to_string(depth) +
                                 " levels deep (a scene file holds at most " + std::to_string(kMaxNodeDepth) + ")");
    }
    io::writeTextAtomically(path, serializeScene(scene));
}

}  // namespace sdfwb::scene
