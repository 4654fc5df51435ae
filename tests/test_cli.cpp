// The command line: outputs and sidecar of `render`, and clear errors for bad input.
#include "gl_test_support.h"

#include <nlohmann/json.hpp>

#include <fstream>

namespace sl {

TEST(Cli, RenderWritesImagesPreviewsAndSidecar) {
    // A SAT scene's filtered map is a pass of its own: made only when asked for.
    fs::path plain = test::tempDir("cli_render_plain");
    auto p = test::runCommand(test::shadowlabBinary() + " render --explain --scene " +
                              test::scenePath("contact").string() + " --out " + plain.string());
    ASSERT_EQ(p.exitCode, 0) << p.output;
    EXPECT_TRUE(fs::exists(plain / "final.png"));
    EXPECT_FALSE(fs::exists(plain / "moments_filtered.exr"));
    EXPECT_EQ(p.output.find("sat-resolve "), std::string::npos) << p.output;
    EXPECT_NE(p.output.find("left out: sat-resolve"), std::string::npos) << p.output;

    fs::path out = test::tempDir("cli_render");
    auto r = test::runCommand(test::shadowlabBinary() + " render --explain --filtered-moments --scene " +
                              test::scenePath("contact").string() + " --out " + out.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (const char* f : {"final.exr", "final.png", "shadow.exr", "shadow.png", "moments_raw.exr",
                          "moments_raw.png", "moments_filtered.exr", "moments_filtered.png",
                          "sat.exr", "render.json"})
        EXPECT_TRUE(fs::exists(out / f)) << f;
    EXPECT_NE(r.output.find("sat-rows"), std::string::npos) << r.output;  // --explain
    // The resolve is an output only: the frame is the same bytes either way.
    auto hashes = [](const fs::path& dir) {
        return nlohmann::json::parse(std::ifstream(dir / "render.json"))["sha256"];
    };
    for (const char* f : {"final.exr", "shadow.exr", "moments_raw.exr"})
        EXPECT_EQ(hashes(plain)[f], hashes(out)[f]) << f;
    EXPECT_NE(r.output.find(" ms"), std::string::npos) << r.output;
    auto sidecar = nlohmann::json::parse(std::ifstream(out / "render.json"));
    EXPECT_EQ(sidecar["solution"], "reference");
    EXPECT_FALSE(sidecar["mesaVersion"].get<std::string>().empty());
    EXPECT_NE(sidecar["renderer"].get<std::string>().find("llvmpipe"), std::string::npos);
    EXPECT_EQ(sidecar["sha256"]["final.exr"].get<std::string>().size(), 64u);
    EXPECT_EQ(sidecar["passes"].size(), 5u);  // shadow, 2 scans, resolve, lighting
}

// Without --out a render goes to out/<scene name>/ under the current folder, never loose into out/.
TEST(Cli, RenderWithoutOutWritesOneFolderPerScene) {
    const fs::path dir = test::tempDir("cli_render_default_out");
    auto r = test::runCommand("cd '" + dir.string() + "' && " + test::shadowlabBinary() +
                              " render --scene " + test::scenePath("unlit_no_shadow").string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(fs::exists(dir / "out/unlit_no_shadow/final.png")) << r.output;
    EXPECT_TRUE(fs::exists(dir / "out/unlit_no_shadow/render.json")) << r.output;
    EXPECT_FALSE(fs::exists(dir / "out/final.png")) << r.output;
    EXPECT_NE(r.output.find("wrote out/unlit_no_shadow/"), std::string::npos) << r.output;
}

TEST(Cli, MalformedSceneNamesFileKeyAndExpectation) {
    fs::path dir = test::tempDir("cli_bad_scene");
    std::ofstream(dir / "bad.json")
        << R"({"camera": {"position": [0,1,5], "target": [0,0,0]}, "lights": [],
              "objects": [{"shape": "sphere", "radius": "big"}]})";
    auto r = test::runCommand(test::shadowlabBinary() + " render --scene " +
                              (dir / "bad.json").string() + " --out " + (dir / "out").string());
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("bad.json"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("/objects/0/radius"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("expected"), std::string::npos) << r.output;
}

TEST(Cli, BrokenStudentShaderReportsFileLineAndExitCode) {
    fs::path dir = test::tempDir("cli_broken_shader");
    for (const auto& name : stageFileNames())
        fs::copy_file(test::root() / "reference" / name, dir / name);
    std::ofstream(dir / "moments.glsl") << "float relativeDepth(float d, vec2 r) { return d }\n";
    auto r = test::runCommand(test::shadowlabBinary() + " render --scene " +
                              test::scenePath("classic").string() + " --solution " + dir.string() +
                              " --out " + (dir / "out").string());
    EXPECT_EQ(r.exitCode, 3) << r.output;
    EXPECT_NE(r.output.find("moments.glsl:1:"), std::string::npos) << r.output;
}

TEST(Cli, UnknownSolutionFolderIsNamed) {
    auto r = test::runCommand(test::shadowlabBinary() + " render --scene " +
                              test::scenePath("classic").string() + " --solution /nonexistent/x");
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.output.find("/nonexistent/x"), std::string::npos) << r.output;
}

// compare --sheet-only (./kit demo's sheets): the same sheet and technique images, nothing else.
TEST(Cli, CompareSheetOnlyWritesTheSameSheetAndOnlyEachTechniquesFinalImage) {
    const fs::path out = test::tempDir("cli_compare");
    const std::string base = test::shadowlabBinary() + " compare --scene " + test::scenePath("classic").string() +
                             " --techniques hard,vsm,msm4 --solution reference --size 64 --out ";
    auto full = test::runCommand(base + (out / "full").string());
    ASSERT_EQ(full.exitCode, 0) << full.output;
    auto sheet = test::runCommand(base + (out / "sheet").string() + " --sheet-only");
    ASSERT_EQ(sheet.exitCode, 0) << sheet.output;
    int files = 0;
    for (const auto& e : fs::recursive_directory_iterator(out / "sheet"))
        if (e.is_regular_file()) {
            ++files;
            const std::string name = e.path().filename().string();
            EXPECT_TRUE(name == "final.png" || name == "sheet.png" || name == "sheet.html") << e.path();
        }
    EXPECT_EQ(files, 3 + 2);  // a final.png per technique, the sheet's PNG and HTML
    EXPECT_TRUE(fs::exists(out / "full" / "vsm" / "final.exr"));
    // The technique images are the same bytes; the sheet itself labels each with its time.
    for (const char* f : {"hard/final.png", "vsm/final.png", "msm4/final.png"}) {
        ASSERT_TRUE(fs::exists(out / "sheet" / f)) << f;
        EXPECT_TRUE(test::readFile(out / "sheet" / f) == test::readFile(out / "full" / f)) << f << " differs";
    }
    EXPECT_GT(fs::file_size(out / "sheet" / "sheet.png"), fs::file_size(out / "sheet" / "vsm" / "final.png"));
}

TEST(Cli, BenchRunsAndReportsRatios) {
    auto r = test::runCommand(test::shadowlabBinary() + " bench --size 64 --repeats 3");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("| copy |"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("gaussian r=8, y"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("sat, rows + columns"), std::string::npos) << r.output;
}

}  // namespace sl
