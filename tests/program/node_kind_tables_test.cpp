// The node-kind table and the tables keyed by it: every kind sits in enum order,
// compiles, has bounds, and is documented in docs/scene-format.md as the code has it.

#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include <gtest/gtest.h>

#include "program/bounds.h"
#include "program/compile_scene.h"
#include "scene/scene.h"
#include "support/source_tree.h"

namespace sdfwb {
namespace {

using scene::KindSpec;
using scene::Node;
using scene::NodeKind;

// A node of `spec` at its defaults with as few children as it needs (a sphere each).
Node minimalNode(const KindSpec& spec) {
    Node node = Node::make(spec.kind);
    for (int i = 0; i < std::max(spec.minChildren, spec.maxChildren < 0 ? 2 : 0); ++i) {
        node.children.push_back(Node::make(NodeKind::Sphere));
    }
    return node;
}

TEST(NodeKindTable, ListsEveryKindInEnumOrder) {
    ASSERT_EQ(scene::allKinds().size(), static_cast<size_t>(scene::kNodeKindCount));
    for (int i = 0; i < scene::kNodeKindCount; ++i) {
        EXPECT_EQ(static_cast<int>(scene::allKinds()[static_cast<size_t>(i)].kind), i);
    }
}

TEST(NodeKindTable, EveryKindCompilesToInstructionsThatWriteTheResult) {
    for (const KindSpec& spec : scene::allKinds()) {
        scene::Scene s;
        s.root = minimalNode(spec);
        program::Program p = program::compileScene(s);
        ASSERT_FALSE(p.code.empty()) << spec.name;
        bool written = false;
        for (const program::Instruction& in : p.code) {
            bool writesSample = program::opcodeInfo(in.op).opClass != program::OpClass::Point;
            written = written || (writesSample && in.dst == p.result);
        }
        EXPECT_TRUE(written) << spec.name << ": no instruction writes the result register";
    }
}

TEST(NodeKindTable, EveryKindHasBoundsThatContainItsChild) {
    for (const KindSpec& spec : scene::allKinds()) {
        program::Bounds b = program::nodeBounds(minimalNode(spec));
        EXPECT_FALSE(b.empty) << spec.name;
        if (!b.infinite && spec.category != scene::NodeCategory::Primitive &&
            spec.category != scene::NodeCategory::Boolean) {
            // a unary operator at its defaults keeps its unit sphere's centre inside
            EXPECT_LE(b.min.x, 0.0) << spec.name;
            EXPECT_GE(b.max.x, 0.0) << spec.name;
        }
    }
}

// A chain of a thousand operators: the compiler and the bounds walk must not
// depend on a deep call stack of their own (the loader limits depth, not this).
TEST(NodeKindTable, ADeepChainOfOperatorsCompilesAndHasBounds) {
    Node chain = Node::make(NodeKind::Sphere);
    const NodeKind operators[] = {NodeKind::Translate, NodeKind::Rotate, NodeKind::Twist, NodeKind::Scale};
    for (int i = 0; i < 1000; ++i) {
        Node parent = Node::make(operators[i % 4]);
        if (operators[i % 4] == NodeKind::Translate) parent.set("offset", glm::dvec3(0.001, 0, 0));
        parent.children.push_back(std::move(chain));
        chain = std::move(parent);
    }
    program::Bounds b = program::nodeBounds(chain);
    EXPECT_FALSE(b.empty);
    EXPECT_FALSE(b.infinite);
    scene::Scene s;
    s.root = std::move(chain);
    program::Program p = program::compileScene(s);
    EXPECT_GT(p.code.size(), 750u);
}

std::string readDoc(const std::string& name) {
    std::ifstream in(sdfwb::test::sourceDir() + "/docs/" + name);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// Rows of the tables whose header starts with "| kind |": the kinds named in the
// first cell, each with the row's field names and its label (the last cell).
struct DocRow {
    std::string kind;
    std::set<std::string> fields;
    std::string label;
};

std::vector<DocRow> documentedKinds(const std::string& doc) {
    std::vector<DocRow> rows;
    std::istringstream lines(doc);
    std::string line;
    bool inTable = false;
    const std::regex name("`([a-z_]+)`");
    const std::regex field("`([a-z_]+)` \\(");
    while (std::getline(lines, line)) {
        if (line.rfind("| kind |", 0) == 0) {
            inTable = true;
            continue;
        }
        if (!inTable || line.rfind("|---", 0) == 0) continue;
        if (line.rfind("|", 0) != 0) {
            inTable = false;
            continue;
        }
        std::vector<std::string> cells;
        std::stringstream row(line.substr(1));
        for (std::string cell; std::getline(row, cell, '|');) cells.push_back(cell);
        std::set<std::string> fields;
        for (std::sregex_iterator it(cells[1].begin(), cells[1].end(), field), end; it != end; ++it) {
            fields.insert((*it)[1]);
        }
        std::string label = cells.back();
        label.erase(0, label.find_first_not_of(' '));
        label.erase(label.find_last_not_of(' ') + 1);
        for (std::sregex_iterator it(cells[0].begin(), cells[0].end(), name), end; it != end; ++it) {
            rows.push_back({(*it)[1], fields, label});
        }
    }
    return rows;
}

TEST(NodeKindTable, DocsListEveryKindInTableOrderWithItsFieldsAndLabel) {
    std::vector<DocRow> rows = documentedKinds(readDoc("scene-format.md"));
    std::vector<std::string> documented, expected;
    for (const DocRow& row : rows) documented.push_back(row.kind);
    for (const KindSpec& spec : scene::allKinds()) expected.emplace_back(spec.name);
    ASSERT_EQ(documented, expected) << "docs/scene-format.md's kind tables must list every kind in table order";
    for (size_t i = 0; i < rows.size(); ++i) {
        const KindSpec& spec = scene::allKinds()[i];
        EXPECT_EQ(rows[i].label, spec.quality == scene::DistanceQuality::Exact ? "exact" : "bound") << spec.name;
        std::set<std::string> fields;
        for (const scene::FieldSpec& f : spec.fields) {
            if (f.type != scene::FieldType::Material && f.type != scene::FieldType::Choice) fields.insert(std::string(f.name));
        }
        for (const std::string& f : fields) {
            EXPECT_TRUE(rows[i].fields.contains(f)) << spec.name << "." << f << " is not documented";
        }
    }
}

}  // namespace
}  // namespace sdfwb
