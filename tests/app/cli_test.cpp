// Runs the sdf-workbench executable: snapshots, error messages and exit codes,
// no partial files, compare's verdicts.

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include "cli_process.h"
#include "support/source_tree.h"

namespace {

using sdfwb::test::Cli;
using sdfwb::test::ProcessResult;
using sdfwb::test::run;
namespace fs = std::filesystem;

TEST_F(Cli, RenderWritesTheImageWithMetadataAndPrintsItsPath) {
    fs::path out = path("snapshot.png");
    ProcessResult r = run(std::string("render ") + sdfwb::test::sourceDir() + "/scenes/default.json -o " +
                          out.string() + " --size 64x36 --stats");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find(out.string()), std::string::npos);
    EXPECT_NE(r.output.find("hit ratio"), std::string::npos);
    auto in = OIIO::ImageInput::open(out.string());
    ASSERT_TRUE(in);
    EXPECT_EQ(in->spec().width, 64);
    EXPECT_EQ(in->spec().get_string_attribute("sdfwb:scene"), "default");
    EXPECT_EQ(in->spec().get_string_attribute("sdfwb:backend"), "cpu");
    EXPECT_FALSE(in->spec().get_string_attribute("sdfwb:renderSeconds").empty());
    EXPECT_EQ(filesInFolder(), 1u);
}

// Mesh export (issue 13): the file is written, bad arguments fail before any
// work with one line, and nothing is left behind.
TEST_F(Cli, MeshWritesTheSurfaceAndRefusesBadArgumentsFirst) {
    fs::path out = path("scene.ply");
    ProcessResult r = run("mesh " + sdfwb::test::sourceDir() + "/scenes/default.json -o " + out.string() +
                          " --resolution 32");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("triangles"), std::string::npos) << r.output;
    EXPECT_GT(fs::file_size(out), 1000u);
    r = run("mesh -o " + path("x.stl").string() + " --resolution 5000");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(r.output, "sdf-workbench mesh: resolution must be 8 to 512 (got 5000)\n");
    r = run("mesh -o " + path("x.png").string());
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.output.find("unsupported mesh format \".png\" (use .stl, .obj or .ply)"), std::string::npos);
    r = run("mesh " + sdfwb::test::sourceDir() + "/scenes/primitives/plane.json -o " + path("p.obj").string());
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.output.find("no bounded surface"), std::string::npos) << r.output;
    EXPECT_EQ(filesInFolder(), 1u);  // the first mesh only
}

TEST_F(Cli, RenderWithoutASceneUsesTheBuiltInDefaultFromAnyFolder) {
    fs::path out = path("builtin.exr");
    ProcessResult r = run("render -o " + out.string() + " --size 32x18 --aa 1");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(fs::exists(out));
}

TEST_F(Cli, GlBackendRendersHeadlessAndDumpsItsShader) {
    fs::path out = path("gl.png"), shader = path("scene.frag");
    ProcessResult r = run(std::string("render ") + sdfwb::test::sourceDir() + "/scenes/default.json -o " +
                          out.string() + " --size 48x27 --backend gl --stats --dump-shader " + shader.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("llvmpipe"), std::string::npos) << r.output;
    EXPECT_TRUE(fs::exists(out));
    std::ifstream dumped(shader);
    std::string text((std::istreambuf_iterator<char>(dumped)), {});
    EXPECT_NE(text.find("Sample map(vec3 p)"), std::string::npos);
}

TEST_F(Cli, InvalidSceneGivesOneLinePerProblemAndNoFile) {
    fs::path scene = path("bad.json"), out = path("out.png");
    std::ofstream(scene) << R"({"format": "sdf-workbench-scene", "version": 1, "root": {"kind": "sphere", "radius": -1}})";
    ProcessResult r = run("render " + scene.string() + " -o " + out.string());
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(r.output, "sdf-workbench render: " + scene.string() + ": root.radius: must be > 0 (got -1)\n");
    EXPECT_FALSE(fs::exists(out));
}

TEST_F(Cli, AMissingTextureImageIsNamedByItsFieldAndWritesNothing) {
    fs::path scene = path("textured.json"), out = path("out.png");
    std::ofstream(scene) << R"({"format": "sdf-workbench-scene", "version": 1,
        "materials": [{"name": "wood", "texture": "image", "texture_image": "wood.png"}],
        "root": {"kind": "sphere", "material": "wood"}})";
    ProcessResult r = run("render " + scene.string() + " -o " + out.string());
    EXPECT_EQ(r.exitCode, 2);
    const std::string expected = "sdf-workbench render: " + scene.string() +
                                 ": materials[0].texture_image: cannot read image " + path("wood.png").string() + ": ";
    EXPECT_EQ(r.output.rfind(expected, 0), 0u) << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1);
    EXPECT_FALSE(fs::exists(out));
}

TEST_F(Cli, MalformedJsonNamesLineAndColumn) {
    fs::path scene = path("broken.json");
    std::ofstream(scene) << "{\n  \"format\": \"sdf-workbench-scene\"\n  \"version\": 1\n}";
    ProcessResult r = run("render " + scene.string() + " -o " + path("x.png").string());
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.output.find(scene.string() + ": line 3, column 11: invalid JSON: syntax error while parsing object - unexpected string literal; expected '}'"), std::string::npos) << r.output;
}

TEST_F(Cli, BadOutputsFailBeforeRenderingAndLeaveNothing) {
    ProcessResult format = run("render -o " + path("x.bmp").string() + " --size 8x8");
    EXPECT_NE(format.exitCode, 0);
    EXPECT_NE(format.output.find("unknown image format '.bmp'"), std::string::npos) << format.output;
    ProcessResult folder = run("render -o " + path("missing/x.png").string() + " --size 8x8");
    EXPECT_NE(folder.exitCode, 0);
    EXPECT_NE(folder.output.find("does not exist"), std::string::npos) << folder.output;
    ProcessResult missing = run("render " + path("nothing.json").string() + " -o " + path("y.png").string());
    EXPECT_NE(missing.exitCode, 0);
    EXPECT_NE(missing.output.find("cannot read"), std::string::npos) << missing.output;
    EXPECT_EQ(filesInFolder(), 0u);
}

TEST_F(Cli, CompareSaysWhetherTheThresholdsHold) {
    fs::path a = path("a.png"), b = path("b.png"), c = path("c.png"), diff = path("diff.png");
    ASSERT_EQ(run("render -o " + a.string() + " --size 40x24 --aa 1").exitCode, 0);
    ASSERT_EQ(run("render -o " + b.string() + " --size 40x24 --aa 1 --backend gl").exitCode, 0);
    ASSERT_EQ(run("render -o " + c.string() + " --size 40x24 --aa 2").exitCode, 0);
    ProcessResult same = run("compare " + a.string() + " " + b.string() + " --diff " + diff.string());
    EXPECT_EQ(same.exitCode, 0) << same.output;
    EXPECT_NE(same.output.find("result: pass"), std::string::npos);
    EXPECT_TRUE(fs::exists(diff));
    ProcessResult different = run("compare " + a.string() + " " + c.string());
    EXPECT_EQ(different.exitCode, 1) << different.output;
    EXPECT_NE(different.output.find("max abs error"), std::string::npos);
}

TEST_F(Cli, HelpDescribesEveryRenderOption) {
    ProcessResult r = run("render --help");
    EXPECT_EQ(r.exitCode, 0);
    for (const char* option : {"--output", "--size", "--aa", "--threads", "--backend", "--stats", "--precision",
                               "--heat", "--dump-shader"}) {
        EXPECT_NE(r.output.find(option), std::string::npos) << option;
    }
}

}  // namespace

namespace {

TEST_F(Cli, ImplicitizePrintsTheEquationAndItsJson) {
    ProcessResult text = run("implicitize \"x = u*v; y = v; z = u^2\"");
    ASSERT_EQ(text.exitCode, 0) << text.output;
    EXPECT_EQ(text.output.substr(0, text.output.find('\n')), "y^2*z - x^2 = 0");
    ProcessResult json = run("implicitize \"x = u*v; y = v; z = u^2\" --json");
    ASSERT_EQ(json.exitCode, 0) << json.output;
    EXPECT_EQ(json.output.find("{\"generators\":[\"y^2*z - x^2\"],\"degree\":3,\"terms\":2,"
                               "\"method\":\"substitution+elimination\",\"seconds\":"),
              0u)
        << json.output;
}

TEST_F(Cli, ImplicitizeConvertsTrigonometryExactly) {
    ProcessResult torus = run("implicitize \"x = (2 + cos(v))*cos(u); y = (2 + cos(v))*sin(u); z = sin(v)\"");
    ASSERT_EQ(torus.exitCode, 0) << torus.output;
    EXPECT_NE(torus.output.find("x^4 + 2*x^2*y^2 + y^4 + 2*x^2*z^2 + 2*y^2*z^2 + z^4 - 10*x^2 - 10*y^2 + 6*z^2 + 9 = 0"),
              std::string::npos)
        << torus.output;
}

TEST_F(Cli, ImplicitizeTakesTheEliminationOrder) {
    // A curve needs several generators, and which ones depends on the order.
    ProcessResult lex = run("implicitize \"x = t; y = t^2; z = t^3\" --order lex --json");
    ASSERT_EQ(lex.exitCode, 0) << lex.output;
    EXPECT_EQ(lex.output.find("{\"generators\":[\"y^3 - z^2\",\"x*z - y^2\",\"x*y - z\",\"x^2 - y\"],"), 0u)
        << lex.output;
    ProcessResult fallback = run("implicitize \"x = t; y = t^2; z = t^3\" --json");
    EXPECT_EQ(fallback.output.find("{\"generators\":[\"y^2 - x*z\",\"x*y - z\",\"x^2 - y\"],"), 0u)
        << fallback.output;
    ProcessResult dense = run("implicitize \"x = u; y = v; z = w\"");
    EXPECT_EQ(dense.output.substr(0, dense.output.find('\n')),
              "no equation: the image is dense (the elimination ideal is zero)");
    ProcessResult unknown = run("implicitize \"x = t; y = t^2; z = t^3\" --order revlex");
    EXPECT_EQ(unknown.exitCode, 2);
    EXPECT_EQ(unknown.output,
              "sdf-workbench implicitize: --order: revlex not in {elimination,elimination-deglex,elimination-lex,lex} "
              "(see sdf-workbench implicitize --help)\n");
}

TEST_F(Cli, GroebnerPrintsAReducedBasisInInputSyntax) {
    ProcessResult r = run("groebner \"x^2 + y^2 + z^2 - 1; x - y; y - z^2\" --vars x,y,z --order degrevlex --json");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(r.output.find("{\"basis\":[\"x - y\",\"z^2 - y\",\"y^2 + 1/2*y - 1/2\"],\"seconds\":"), 0u) << r.output;
}

TEST_F(Cli, AlgebraInputErrorsAreOneLineWithAColumn) {
    ProcessResult sqrt = run("implicitize \"x = sqrt(u); y = v; z = u\"");
    EXPECT_EQ(sqrt.exitCode, 2);
    EXPECT_EQ(sqrt.output, "sdf-workbench implicitize: column 5: 'sqrt' is not a polynomial or rational function\n");
    ProcessResult vars = run("groebner \"x^2 - y\" --vars x,sin");
    EXPECT_EQ(vars.exitCode, 2);
    EXPECT_EQ(vars.output, "sdf-workbench groebner: --vars: 'sin': 'sin' is the name of a built-in function\n");
    ProcessResult unknown = run("groebner \"x^2 - w\" --vars x,y");
    EXPECT_EQ(unknown.exitCode, 2);
    EXPECT_NE(unknown.output.find("'w'"), std::string::npos) << unknown.output;
}

// A lit sphere on a floor, small enough to sweep in a test.
void writeTinyScene(const fs::path& file) {
    std::ofstream(file) << R"({"format": "sdf-workbench-scene", "version": 1, "name": "tiny",
        "render": {"aa": 1, "max_steps": 32, "shadows": "hard", "shadow_steps": 16, "ao_samples": 0},
        "environment": {"ground": {"enabled": true}},
        "root": {"kind": "sphere", "radius": 1}})";
}

TEST_F(Cli, TradeoffReportsFrontsAndPlotsAndRendersTheReferenceOnce) {
    // relative paths, as a user in the scenes' folder gives them: the report names the scene so
    struct InFolder {
        fs::path previous = fs::current_path();
        explicit InFolder(const fs::path& folder) { fs::current_path(folder); }
        ~InFolder() { fs::current_path(previous); }
    } inFolder(folder_);
    fs::path scene = "tiny.json", report = "report.md", plots = "plots", cache = "cache";
    writeTinyScene(scene);
    std::string arguments = "tradeoff " + scene.string() + " --size 16x9 --repetitions 1 --knobs max_steps=8,64 aa=2 " +
                            "ao_samples --report " + report.string() + " --plot-dir " + plots.string() + " --cache " +
                            cache.string();
    ProcessResult first = run(arguments);
    ASSERT_EQ(first.exitCode, 0) << first.output;
    std::ifstream in(report);
    std::string text((std::istreambuf_iterator<char>(in)), {});
    EXPECT_NE(text.find("## Summary"), std::string::npos) << text;
    EXPECT_NE(text.find("| tiny.json | cpu |"), std::string::npos) << text;
    EXPECT_NE(text.find("| tiny.json | gl |"), std::string::npos) << text;
    EXPECT_NE(text.find("| max_steps=8 | gl |"), std::string::npos) << text;
    EXPECT_NE(text.find("| aa=2 | cpu |"), std::string::npos) << text;
    EXPECT_NE(text.find("| default | cpu |"), std::string::npos) << text;
    EXPECT_NE(text.find("front"), std::string::npos) << text;
    EXPECT_NE(text.find("not swept: `ao_samples` (AO off)"), std::string::npos) << text;
    EXPECT_NE(text.find("Reference: double-precision CPU, AA 2, epsilon 0.0001, max steps 320"), std::string::npos)
        << text;
    EXPECT_NE(text.find("rendered in"), std::string::npos);
    EXPECT_NE(text.find("](plots/tiny.png)"), std::string::npos) << text;
    auto png = OIIO::ImageInput::open((plots / "tiny.png").string());
    ASSERT_TRUE(png);
    EXPECT_GT(png->spec().width, 100);
    // one reference, and the measurements the workbench's estimate reads
    auto cached = [&] {
        std::vector<std::string> names;
        for (const auto& entry : fs::directory_iterator(cache)) names.push_back(entry.path().filename().string());
        std::sort(names.begin(), names.end());
        return names;
    };
    std::vector<std::string> files = cached();
    ASSERT_EQ(files.size(), 2u);
    auto ends = [](const std::string& name, const std::string& tail) {
        return name.size() > tail.size() && name.compare(name.size() - tail.size(), tail.size(), tail) == 0;
    };
    EXPECT_EQ(std::count_if(files.begin(), files.end(), [&](auto& f) { return ends(f, ".measured.json"); }), 1);
    EXPECT_EQ(std::count_if(files.begin(), files.end(), [&](auto& f) { return ends(f, ".ref"); }), 1);

    ProcessResult second = run(arguments);
    ASSERT_EQ(second.exitCode, 0) << second.output;
    std::ifstream again(report);
    std::string secondText((std::istreambuf_iterator<char>(again)), {});
    EXPECT_NE(secondText.find("(cached)"), std::string::npos);
    EXPECT_EQ(cached(), files);
}

TEST_F(Cli, TradeoffOutOfBudgetSaysWhatItSkipped) {
    fs::path scene = path("tiny.json"), report = path("report.md");
    writeTinyScene(scene);
    // a nanosecond has passed before the first render can start
    ProcessResult r = run("tradeoff " + scene.string() + " --backend cpu --size 16x9 --knobs max_steps=8 --budget 1e-9 --report " +
                          report.string() + " --cache " + path("cache").string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("the budget ran out; 3 renders skipped"), std::string::npos) << r.output;
    std::ifstream in(report);
    std::string text((std::istreambuf_iterator<char>(in)), {});
    EXPECT_NE(text.find("skipped for the budget: reference, default, max_steps=8"), std::string::npos) << text;
    EXPECT_FALSE(fs::exists(path("cache")));
}

TEST_F(Cli, TradeoffBadArgumentsFailInOneLineAndWriteNothing) {
    fs::path scene = path("tiny.json"), report = path("report.md");
    writeTinyScene(scene);
    ProcessResult knob = run("tradeoff " + scene.string() + " --knobs speed --report " + report.string());
    EXPECT_EQ(knob.exitCode, 2);
    EXPECT_EQ(knob.output.find("sdf-workbench tradeoff: --knobs: unknown knob 'speed' (known: epsilon,"), 0u)
        << knob.output;
    ProcessResult value = run("tradeoff " + scene.string() + " --knobs max_steps=0 --report " + report.string());
    EXPECT_EQ(value.exitCode, 2);
    EXPECT_NE(value.output.find("max_steps=0: render.max_steps"), std::string::npos) << value.output;
    ProcessResult plot = run("tradeoff " + scene.string() + " " + scene.string() + " --plot " +
                             path("p.png").string() + " --report " + report.string());
    EXPECT_NE(plot.exitCode, 0);
    EXPECT_NE(plot.output.find("--plot takes one scene"), std::string::npos) << plot.output;
    ProcessResult folder = run("tradeoff " + scene.string() + " --report " + path("missing/r.md").string());
    EXPECT_NE(folder.exitCode, 0);
    EXPECT_NE(folder.output.find("does not exist"), std::string::npos) << folder.output;
    EXPECT_EQ(filesInFolder(), 1u);  // the scene only
}

}  // namespace
