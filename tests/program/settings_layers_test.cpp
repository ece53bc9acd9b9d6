// Layout checks of the parameter buffer and the shared structs: every packed
// component is read back by its unpacker, every constructor call of a shared
// struct passes every member, and every setting and material field reaches the
// parameter buffer. These fail when a field is left out of one layer.

#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "program/compile_scene.h"
#include "scene/scene_json.h"
#include "scene/settings_table.h"
#include "sdf/glsl_sources.h"
#include "sdf/shared.h"
#include "support/source_tree.h"

namespace sdfwb {
namespace {

using glm::dvec4;
namespace shared = sdf::f64;

// For each component of a block: set it to a marker, unpack, pack again; the
// marker must come back, or that component is packed and never read (or read
// from somewhere the packer does not write).
template <typename Unpack, typename Pack>
void expectPackUndoesUnpack(const char* block, int slots, Unpack unpack, Pack pack, std::vector<int> unused = {}) {
    for (int slot = 0; slot < slots; ++slot) {
        for (int c = 0; c < 4; ++c) {
            if (std::find(unused.begin(), unused.end(), 4 * slot + c) != unused.end()) continue;
            std::vector<dvec4> q(static_cast<size_t>(slots), dvec4(2.0));
            q[static_cast<size_t>(slot)][c] = 3.0;
            auto unpacked = unpack(q);
            EXPECT_EQ(pack(unpacked, slot)[c], 3.0) << block << " slot " << slot << " component " << c;
        }
    }
}

TEST(ParameterBlocks, EachPackerUndoesItsUnpacker) {
    expectPackUndoesUnpack(
        "TraceSettings", shared::TRACE_SLOTS,
        [](const std::vector<dvec4>& q) {
            return shared::traceSettingsFromSlots(q[0], q[1], q[2], q[3], q[4], q[5], q[6]);
        },
        [](const shared::TraceSettings& s, int i) { return shared::traceSettingsSlot(s, i); }, {23});
    expectPackUndoesUnpack(
        "Camera", shared::CAMERA_SLOTS,
        [](const std::vector<dvec4>& q) { return shared::cameraFromSlots(q[0], q[1], q[2], q[3]); },
        [](const shared::Camera& c, int i) { return shared::cameraSlot(c, i); }, {7, 11, 15});
    expectPackUndoesUnpack(
        "Light", shared::LIGHT_SLOTS, [](const std::vector<dvec4>& q) { return shared::lightFromSlots(q[0], q[1]); },
        [](const shared::Light& l, int i) { return shared::lightSlot(l, i); }, {7});
    expectPackUndoesUnpack(
        "EnvironmentMap", shared::ENVIRONMENT_SLOTS,
        [](const std::vector<dvec4>& q) { return shared::environmentFromSlots(q[0]); },
        [](const shared::EnvironmentMap& e, int i) { return shared::environmentSlot(e, i); });
    expectPackUndoesUnpack(
        "Material", shared::MATERIAL_SLOTS,
        [](const std::vector<dvec4>& q) { return shared::materialFromSlots(q[0], q[1], q[2], q[3], q[4], q[5]); },
        [](const shared::Material& m, int i) { return shared::materialSlot(m, i); });
}

TEST(ParameterBlocks, BlocksFollowEachOtherAheadOfTheMaterials) {
    EXPECT_EQ(shared::CAMERA_SLOT, shared::TRACE_SLOT + shared::TRACE_SLOTS);
    EXPECT_EQ(shared::LIGHT_SLOT, shared::CAMERA_SLOT + shared::CAMERA_SLOTS);
    EXPECT_EQ(shared::ENVIRONMENT_SLOT, shared::LIGHT_SLOT + shared::MAX_LIGHTS * shared::LIGHT_SLOTS);
    EXPECT_EQ(shared::MATERIAL_SLOT, shared::ENVIRONMENT_SLOT + shared::ENVIRONMENT_SLOTS);
    scene::Scene s;
    EXPECT_EQ(program::compileScene(s).params.size(),
              static_cast<size_t>(shared::MATERIAL_SLOT + shared::MATERIAL_SLOTS));
}

// Arguments of the call whose '(' is at `open`: top-level commas + 1.
int argumentCount(const std::string& text, size_t open) {
    int depth = 0, count = 1;
    for (size_t i = open; i < text.size(); ++i) {
        char c = text[i];
        if (c == '(') ++depth;
        if (c == ')' && --depth == 0) return text.compare(open, i - open + 1, "()") == 0 ? 0 : count;
        if (c == ',' && depth == 1) ++count;
    }
    return -1;
}

// Every struct of the shared library, and every call of its constructor in the
// library, the sample driver and the generated shader's interface: C++ would
// quietly zero a member a call leaves out, GLSL would refuse it.
TEST(SharedStructs, EveryConstructorCallPassesEveryMember) {
    std::string text = std::regex_replace(std::string(sdf::glslLibrary()) + std::string(sdf::glslSampleDriver()),
                                          std::regex("//[^\n]*"), "");
    std::regex structDef("struct ([A-Za-z]+) \\{([^}]*)\\};");
    int structs = 0, calls = 0;
    for (std::sregex_iterator it(text.begin(), text.end(), structDef), end; it != end; ++it) {
        std::string name = (*it)[1], body = (*it)[2];
        int members = static_cast<int>(std::count(body.begin(), body.end(), ';'));
        ++structs;
        std::regex call("[^A-Za-z0-9_]" + name + "\\(");
        for (std::sregex_iterator c(text.begin(), text.end(), call); c != end; ++c) {
            size_t open = static_cast<size_t>(c->position()) + c->length() - 1;
            ++calls;
            EXPECT_EQ(argumentCount(text, open), members) << name << " constructed at: " << text.substr(open, 80);
        }
    }
    EXPECT_GE(structs, 6);  // Material, Sample, Camera, Ray, Light, TraceSettings, ...
    EXPECT_GE(calls, 8);
}

// A valid value different from the row's current one.
template <typename Owner>
void perturb(const scene::Setting<Owner>& row, Owner& owner) {
    using enum scene::SettingType;
    switch (row.type) {
    case Integer: {
        int& v = owner.*std::get<int Owner::*>(row.member);
        v = v > static_cast<int>(row.minimum) ? v - 1 : v + 1;
        return;
    }
    case Real: {
        double& v = owner.*std::get<double Owner::*>(row.member);
        if (row.range == scene::RealRange::Closed || row.range == scene::RealRange::Open) {
            v = v == (row.minimum + row.maximum) / 2 ? (3 * row.minimum + row.maximum) / 4 : (row.minimum + row.maximum) / 2;
        } else {
            v = v * 1.5 + 0.25;
        }
        return;
    }
    case Choice: {
        const auto& access = std::get<scene::ChoiceMember<Owner>>(row.member);
        access.set(owner, (access.get(owner) + 1) % static_cast<int>(row.choices.size()));
        return;
    }
    case Colour:
    case Vector:
    case Direction: owner.*std::get<glm::dvec3 Owner::*>(row.member) += glm::dvec3(0.25, 0.125, 0.5); return;
    case Flag: owner.*std::get<bool Owner::*>(row.member) = !(owner.*std::get<bool Owner::*>(row.member)); return;
    case Text: return;
    case ImageFile: owner.*std::get<std::string Owner::*>(row.member) += "moved.png"; return;
    }
}

bool programsDiffer(const scene::Scene& a, const scene::Scene& b) {
    program::Program p = program::compileScene(a), q = program::compileScene(b);
    // the environment map's block is written by the backends, from these (program/scene_images.h)
    bool environment = p.environmentKind != q.environmentKind || p.environmentFiles != q.environmentFiles ||
                       p.environmentIntensity != q.environmentIntensity;
    return p.params != q.params || p.width != q.width || p.height != q.height || p.aa != q.aa ||
           p.structureKey() != q.structureKey() || environment;
}

scene::Scene sceneUsingAMaterial() {
    scene::Scene s;
    scene::Material m;
    m.name = "m";
    m.texture = scene::TexturePattern::Checker;  // else the texture's scale and colour are inert
    m.bump = scene::BumpPattern::Noise;          // likewise the bump's scale and depth
    s.materials.push_back(m);
    s.root = scene::Node::make(scene::NodeKind::Sphere);
    s.root.set("material", std::string("m"));
    s.environment.ground.enabled = true;
    return s;
}

template <typename Owner, typename Select>
void expectEveryRowReachesTheProgram(const char* table, std::span<const scene::Setting<Owner>> rows, Select select) {
    for (const scene::Setting<Owner>& row : rows) {
        // names; and files, which reach the program only where a map or texture reads them
        if (row.type == scene::SettingType::Text || row.type == scene::SettingType::ImageFile) continue;
        scene::Scene base = sceneUsingAMaterial(), changed = base;
        perturb(row, select(changed));
        EXPECT_TRUE(programsDiffer(base, changed)) << table << "." << row.key << " does not reach the compiled program";
    }
}

TEST(SettingsTables, EverySettingAndMaterialFieldReachesTheCompiledProgram) {
    expectEveryRowReachesTheProgram("render", scene::renderSettings(), [](scene::Scene& s) -> auto& { return s.render; });
    expectEveryRowReachesTheProgram("camera", scene::cameraSettings(), [](scene::Scene& s) -> auto& { return s.camera; });
    expectEveryRowReachesTheProgram("environment", scene::environmentSettings(),
                                    [](scene::Scene& s) -> auto& { return s.environment; });
    expectEveryRowReachesTheProgram("ground", scene::groundSettings(),
                                    [](scene::Scene& s) -> auto& { return s.environment.ground; });
    expectEveryRowReachesTheProgram("light", scene::lightSettings(), [](scene::Scene& s) -> auto& { return s.lights[0]; });
    expectEveryRowReachesTheProgram("material", scene::materialSettings(),
                                    [](scene::Scene& s) -> auto& { return s.materials[0]; });
}

// Every row of every table is read back as written, and documented.
TEST(SettingsTables, EveryRowRoundTripsThroughJsonAndIsDocumented) {
    std::ifstream in(sdfwb::test::sourceDir() + "/docs/scene-format.md");
    std::stringstream doc;
    doc << in.rdbuf();
    auto check = [&](const char* table, auto rows, auto select) {
        for (const auto& row : rows) {
            std::regex documented("\\n\\|[^\\n]*`" + std::string(row.key) + "`[^\\n]*\\|");
            EXPECT_TRUE(std::regex_search(doc.str(), documented)) << table << "." << row.key << " is not in docs/scene-format.md";
            if (row.type == scene::SettingType::Text) continue;
            scene::Scene s = sceneUsingAMaterial();
            perturb(row, select(s));
            EXPECT_EQ(scene::parseScene(scene::serializeScene(s)), s) << table << "." << row.key;
        }
    };
    check("render", scene::renderSettings(), [](scene::Scene& s) -> auto& { return s.render; });
    check("camera", scene::cameraSettings(), [](scene::Scene& s) -> auto& { return s.camera; });
    check("environment", scene::environmentSettings(), [](scene::Scene& s) -> auto& { return s.environment; });
    check("ground", scene::groundSettings(), [](scene::Scene& s) -> auto& { return s.environment.ground; });
    check("light", scene::lightSettings(), [](scene::Scene& s) -> auto& { return s.lights[0]; });
    check("material", scene::materialSettings(), [](scene::Scene& s) -> auto& { return s.materials[0]; });
}

}  // namespace
}  // namespace sdfwb
