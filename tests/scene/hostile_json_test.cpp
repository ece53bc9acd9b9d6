// Hostile scene files: nesting, duplicate keys, stray bytes, huge numbers and
// huge strings end in one short problem line with a location, never a crash.

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>

#include "scene/json_text.h"
#include "scene/scene_json.h"
#include "support/small_stack.h"

namespace sdfwb::scene {
namespace {

std::string document(const std::string& root, const std::string& extra = "") {
    return R"({"format": "sdf-workbench-scene", "version": 1, )" + extra + R"("root": )" + root + "}";
}

std::vector<std::string> problemsOf(std::string_view text) {
    try {
        parseScene(text);
    } catch (const SceneError& error) {
        return error.problems();
    }
    return {};
}

// `depth` translate nodes around a sphere: a tree of depth + 1 levels.
std::string transformChain(int depth) {
    std::string open, close;
    for (int i = 0; i < depth; ++i) {
        open += R"({"kind": "translate", "offset": [0.001, 0, 0], "children": [)";
        close += "]}";
    }
    return open + R"({"kind": "sphere", "radius": 0.5})" + close;
}

TEST(HostileJson, ArraysNestedAnywhereAreRefusedWithTheirPath) {
    const int depth = 100000;
    std::string text = document(R"({"kind": "sphere"})", R"("name": )" + std::string(depth, '[') +
                                                             std::string(depth, ']') + ", ");
    auto problems = problemsOf(text);
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_EQ(problems[0].rfind("name[0][0]", 0), 0u) << problems[0];
    EXPECT_NE(problems[0].find("nested deeper than " + std::to_string(kMaxJsonDepth) + " levels"), std::string::npos);
    EXPECT_LT(problems[0].size(), 300u);
}

TEST(HostileJson, ObjectsNestedAtTheTopAreRefused) {
    std::string text;
    for (int i = 0; i < 50000; ++i) text += R"({"a":)";
    text += "1" + std::string(50000, '}');
    auto problems = problemsOf(text);
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_NE(problems[0].find("nested deeper than"), std::string::npos) << problems[0];
}

TEST(HostileJson, AThousandNestedTransformsLoadAndRoundTrip) {
    Scene scene = parseScene(document(transformChain(1000)));
    const Node* node = &scene.root;
    int depth = 1;
    while (!node->children.empty()) {
        node = &node->children[0];
        ++depth;
    }
    EXPECT_EQ(depth, 1001);
    EXPECT_EQ(node->kind, NodeKind::Sphere);
    EXPECT_EQ(parseScene(serializeScene(scene)), scene);
}

TEST(HostileJson, TheDeepestLegalTreeLoadsOnASmallStack) {
    const std::string text = document(transformChain(kMaxNodeDepth - 1));
    Scene scene;
    std::vector<std::string> problems;
    test::onSmallStack(256 * 1024, [&] {
        try {
            scene = parseScene(text);  // destroyed on this thread's stack, not the small one
        } catch (const SceneError& error) {
            problems = error.problems();
        }
    });
    EXPECT_TRUE(problems.empty()) << problems[0];
    EXPECT_EQ(treeDepth(scene.root), kMaxNodeDepth);
}

TEST(HostileJson, ATreeDeeperThanTheLimitIsOneProblemWithItsPath) {
    auto problems = problemsOf(document(transformChain(kMaxNodeDepth)));
    ASSERT_EQ(problems.size(), 1u) << problems[0];
    EXPECT_NE(problems[0].find("nodes nested deeper than " + std::to_string(kMaxNodeDepth) + " levels"),
              std::string::npos)
        << problems[0];
    EXPECT_EQ(problems[0].rfind("root.children[0].children[0]", 0), 0u) << problems[0];
    EXPECT_LT(problems[0].size(), 300u);
    EXPECT_TRUE(problemsOf(document(transformChain(kMaxNodeDepth - 1))).empty());
}

TEST(HostileJson, DuplicateKeysAreErrors) {
    auto problems = problemsOf(document(R"({"kind": "sphere", "radius": -5, "radius": 0.5})"));
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_EQ(problems[0], "root.radius: duplicate key \"radius\" (each field may be given once)");
    EXPECT_EQ(problemsOf(R"({"format": "sdf-workbench-scene", "version": 1, "version": 1, "root": {"kind": "sphere"}})"),
              std::vector<std::string>{"version: duplicate key \"version\" (each field may be given once)"});
}

TEST(HostileJson, BytesAfterTheDocumentAndNulBytesAreErrors) {
    std::string valid = document(R"({"kind": "sphere"})");
    std::string withNul = valid + std::string(1, '\0') + "garbage";
    auto problems = problemsOf(withNul);
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_EQ(problems[0], "line 1, column " + std::to_string(valid.size() + 1) +
                               ": invalid JSON: a NUL byte (a scene file is UTF-8 text)");
    problems = problemsOf(valid + "\n{}");
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_EQ(problems[0].rfind("line 2, column 1: invalid JSON: syntax error", 0), 0u) << problems[0];
}

TEST(HostileJson, VersionsOutsideTheRangeAreNamedAsWritten) {
    for (std::string version : {"4294967297", "18446744073709551615", "-1", "-9223372036854775808", "0"}) {
        auto problems = problemsOf(R"({"format": "sdf-workbench-scene", "version": )" + version +
                                   R"(, "root": {"kind": "sphere"}})");
        ASSERT_EQ(problems.size(), 1u) << version;
        EXPECT_EQ(problems[0], "version: unsupported version " + version + " (this build reads versions 1 to 1)");
    }
}

TEST(HostileJson, InfiniteNumbersNameLineAndColumn) {
    auto problems = problemsOf("{\"format\": \"sdf-workbench-scene\", \"version\": 1,\n \"root\": {\"kind\": "
                               "\"sphere\", \"radius\": 1e999}}");
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_EQ(problems[0], "line 2, column 39: invalid JSON: number overflow \"1e999\" (numbers must be finite)");
}

TEST(HostileJson, UserStringsInMessagesAreEscapedAndShort) {
    std::string hugeKey(5'000'000, 'k');
    auto problems = problemsOf(document(R"({"kind": "sphere", ")" + hugeKey + R"(": 1})"));
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_LT(problems[0].size(), 300u);
    EXPECT_NE(problems[0].find("(5000000 bytes)"), std::string::npos) << problems[0];

    problems = problemsOf(document(R"({"kind": "sph\u0000\u001bere"})"));
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_EQ(problems[0].rfind(R"(root.kind: unknown node kind "sph\x00\x1bere")", 0), 0u) << problems[0];

    problems = problemsOf(document(R"({"kind": "sphere"})") + "\"" + std::string(1'000'000, 'x'));
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_LT(problems[0].size(), 300u) << problems[0].substr(0, 300);
}

TEST(HostileJson, ATreeTooDeepToLoadIsNotSavedAndTheOldFileStays) {
    Scene scene = parseScene(document(transformChain(kMaxNodeDepth - 1)));
    EXPECT_EQ(treeDepth(scene.root), kMaxNodeDepth);
    auto path = std::filesystem::temp_directory_path() / ("sdfwb_deep_" + std::to_string(::getpid()) + ".json");
    saveSceneFile(scene, path);
    const std::string saved = serializeScene(scene);
    Node wrapper = Node::make(NodeKind::Union);
    wrapper.children.push_back(scene.root);
    scene.root = wrapper;
    EXPECT_EQ(treeDepth(scene.root), kMaxNodeDepth + 1);
    EXPECT_THROW(saveSceneFile(scene, path), std::runtime_error);
    EXPECT_EQ(serializeScene(loadSceneFile(path)), saved);
    std::filesystem::remove(path);
}

TEST(HostileJson, AbbreviatedPathsKeepStartAndEnd) {
    std::string path = "root";
    for (int i = 0; i < 100; ++i) path += ".children[0]";
    path += ".radius";
    std::string shown = abbreviatedPath(path);
    EXPECT_LT(shown.size(), 160u);
    EXPECT_EQ(shown.rfind("root.children[0]", 0), 0u);
    EXPECT_EQ(shown.substr(shown.size() - 7), ".radius");
    EXPECT_EQ(abbreviatedPath("root.radius"), "root.radius");
}

}  // namespace
}  // namespace sdfwb::scene
