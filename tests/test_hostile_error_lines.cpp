// Hostile input (nothing a student submits may crash or mislead the grader): errors point at the
// student's file and line. Mesa 22.3 reports semantic errors with source string 0 whatever `#line N
// file` said, so an undeclared name in msm.glsl was blamed on shaders/lighting.frag. The assembled
// text is one source string now, mapped back by its line table. Checked with a semantic error (not
// a syntax error) in every stage file, compiled by the renderer as a scene uses it; and #line /
// #extension, which would spoof or break the mapping, are refused with a clear message.
#include "test_grader_support.h"

#include "shader_source.h"

namespace sl {
namespace {

// The renderer's first error for `scene` with `file` = the reference's text plus a function
// using an undeclared name on its last line; that line's number in `line`.
std::string firstError(const std::string& scene, const std::string& file, int& line) {
    const fs::path dir = test::tempDir("error_lines_" + file);
    for (const auto& name : stageFileNames())
        fs::copy_file(test::root() / "reference" / name, dir / name);
    std::string text = test::readFile(dir / file);
    if (!text.empty() && text.back() != '\n') text += '\n';
    line = int(std::count(text.begin(), text.end(), '\n')) + 2;
    text += "float hostileHelper(float zf)\n{ return undeclaredThing + zf; }\n";
    std::ofstream(dir / file) << text;
    test::sharedContext();
    try {
        Scene s = loadScene(test::scenePath(scene).string());
        Renderer renderer(ShaderLibrary::forSolution(dir, test::root()));
        renderer.render(s, planPasses(s));
    } catch (const ShaderError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(HostileErrorLines, ASemanticErrorInEveryStageFileNamesThatFileAndLine) {
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"moments.glsl", "classic"}, {"msm.glsl", "classic"}, {"gaussian_blur.comp", "classic"},
        {"sat.comp", "contact"}, {"sat_lookup.glsl", "contact"}};
    for (const auto& [file, scene] : cases) {
        SCOPED_TRACE(file);
        int line = 0;
        const std::string err = firstError(scene, file, line);
        ASSERT_FALSE(err.empty()) << "no compile error";
        const std::string where = "error_lines_" + file + "/" + file + ":" + std::to_string(line) + ":";
        EXPECT_NE(err.substr(0, err.find('\n')).find(where), std::string::npos)
            << "expected the first line to name " << where << "\n" << err;
        EXPECT_NE(err.find("undeclaredThing"), std::string::npos) << err;
        EXPECT_EQ(err.substr(0, err.find("--- driver log")).find("lighting.frag"), std::string::npos) << err;
    }
}

TEST(HostileErrorLines, LineAndExtensionDirectivesAreRefused) {
    // The assembler refuses them (shadowlab render) ...
    const fs::path dir = test::tempDir("error_lines_directives");
    std::ofstream(dir / "a.glsl") << "float a;\n#line 1 \"shaders/lighting.frag\"\n";
    std::ofstream(dir / "b.glsl") << "float b;\n#extension GL_ARB_gpu_shader_fp64 : enable\n";
    ShaderLibrary lib({}, {dir}, dir);
    for (const char* f : {"a.glsl", "b.glsl"}) {
        try {
            lib.assemble(f, {});
            ADD_FAILURE() << f << ": no error";
        } catch (const ShaderError& e) {
            EXPECT_EQ(std::string(e.what()).rfind(std::string(f) + ":2: error: #", 0), 0u) << e.what();
        }
    }
    // ... and so does the grader's intake, per file, with the line.
    std::string msm = test::readFile(test::root() / "reference" / "msm.glsl");
    std::string moments = test::readFile(test::root() / "reference" / "moments.glsl");
    auto sub = test::makeSubmission("directives", {{"msm.glsl", "#line 40 0\n" + msm},
                                                   {"moments.glsl", "#extension GL_EXT_x : enable\n" + moments}});
    auto g = test::grade("--scenes classic --no-report --submission " + sub.string(),
                         test::tempDir("error_lines_directives_out"));
    ASSERT_EQ(g.run.exitCode, 0) << g.run.output;
    EXPECT_NE(g.output("classic", "msm").find("msm.glsl: refused: line 1: #line is not allowed"),
              std::string::npos) << g.output("classic", "msm");
    EXPECT_NE(g.output("classic", "moments").find("moments.glsl: refused: line 1: #extension is not allowed"),
              std::string::npos) << g.output("classic", "moments");
    EXPECT_TRUE(g.full("classic", "gaussian"));
}

}  // namespace sl
