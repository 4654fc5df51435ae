// Shader loading: #include lookup order, and errors that name the student's file and line.
#include "gl_program.h"
#include "gl_test_support.h"
#include "technique.h"

#include <fstream>

namespace sl {
namespace {

// A solution folder with the reference's files, where `file` is replaced by `text`.
fs::path solutionWith(const std::string& testName, const std::string& file,
                      const std::string& text) {
    fs::path dir = test::tempDir(testName);
    for (const auto& name : stageFileNames())
        fs::copy_file(test::root() / "reference" / name, dir / name);
    test::writeFile(dir / file, text);
    return dir;
}

std::string compileError(const ShaderLibrary& lib, const std::string& vs, const std::string& fs) {
    try {
        GlProgram::graphics(lib, vs, fs, techniqueDefines(ShadowEffect{}));  // msm4, Gaussian
    } catch (const ShaderError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(ShaderSource, CompileErrorNamesStudentFileAndLine) {
    test::sharedContext();
    const std::string msm =
        "// line 1\n// line 2\nfloat momentShadowIntensity(vec4 b, float zf) {\n"
        "    float x = 1.0\n"  // line 4: missing semicolon, reported on line 5
        "    return undefinedThing;\n}\n";
    fs::path dir = solutionWith("compile_error", "msm.glsl", msm);
    ShaderLibrary lib = ShaderLibrary::forSolution(dir, test::root());
    std::string err = compileError(lib, "scene.vert", "lighting.frag");
    ASSERT_FALSE(err.empty());
    const std::string file = lib.displayPath(dir / "msm.glsl");
    EXPECT_EQ(err.rfind(file + ":5:", 0), 0u) << err;  // the first line blames msm.glsl:5
    EXPECT_NE(err.find("--- driver log"), std::string::npos) << err;  // the full log follows
    // Mesa's own log, with the line of the assembled text (one source string).
    EXPECT_NE(err.find("(2): error: syntax error"), std::string::npos) << err;
}

TEST(ShaderSource, ErrorsInsideAnIncludeAndAfterItMapToTheirOwnFiles) {
    test::sharedContext();
    fs::path dir = test::tempDir("include_lines");
    for (const auto& name : stageFileNames())
        fs::copy_file(test::root() / "reference" / name, dir / name);
    test::writeFile(dir / "helper.glsl", "// helper line 1\nfloat helper() { return 1.0 }\n");  // line 2
    test::writeFile(dir / "msm.glsl",
                    "#include \"helper.glsl\"\n"
                    "float momentShadowIntensity(vec4 b, float zf) { return helper(); }\n"
                    "float broken() { return nope; }\n");  // line 3
    ShaderLibrary lib = ShaderLibrary::forSolution(dir, test::root());
    std::string err = compileError(lib, "scene.vert", "lighting.frag");
    EXPECT_NE(err.find(lib.displayPath(dir / "helper.glsl") + ":2:"), std::string::npos) << err;
    // The helper error stops Mesa's parser; check the line after an include separately.
    test::writeFile(dir / "helper.glsl", "float helper() { return 1.0; }\n");
    err = compileError(ShaderLibrary::forSolution(dir, test::root()), "scene.vert",
                       "lighting.frag");
    EXPECT_NE(err.find(lib.displayPath(dir / "msm.glsl") + ":3:"), std::string::npos) << err;
}

TEST(ShaderSource, StageFilesComeFromTheirFolderOthersFromSolutionThenShaders) {
    fs::path a = test::tempDir("lookup_a"), b = test::tempDir("lookup_b");
    test::writeFile(a / "msm.glsl", "");
    test::writeFile(a / "common.glsl", "");
    test::writeFile(b / "common.glsl", "");
    test::writeFile(b / "only_b.glsl", "");
    ShaderLibrary lib({{"msm.glsl", a}}, {b}, test::root());
    EXPECT_EQ(lib.resolve("msm.glsl"), a / "msm.glsl");
    EXPECT_EQ(lib.resolve("common.glsl"), a / "common.glsl");  // solution first
    EXPECT_EQ(lib.resolve("common.glsl", b / "msm.glsl"), b / "common.glsl");  // includer's own
    // A solution's file never reaches into another solution's folder for a helper: a
    // student's msm.glsl (b) graded with the reference's other stages (a).
    ShaderLibrary mixed = ShaderLibrary::mixed(a, {{"msm.glsl", b}}, test::root());
    EXPECT_THROW(mixed.resolve("common_a.glsl", b / "msm.glsl"), ShaderError);
    test::writeFile(a / "common_a.glsl", "");
    EXPECT_EQ(mixed.resolve("common_a.glsl", a / "sat.comp"), a / "common_a.glsl");
    EXPECT_THROW(mixed.resolve("common_a.glsl", b / "msm.glsl"), ShaderError);
    EXPECT_EQ(lib.resolve("only_b.glsl"), b / "only_b.glsl");
    EXPECT_THROW(lib.resolve("absent.glsl"), ShaderError);
}

TEST(ShaderSource, MissingStageFileSaysNotSubmitted) {
    fs::path empty = test::tempDir("missing_stage");
    ShaderLibrary lib = ShaderLibrary::forSolution(empty, test::root());
    try {
        lib.resolve("msm.glsl");
        FAIL() << "no error";
    } catch (const ShaderError& e) {
        EXPECT_NE(std::string(e.what()).find("not submitted"), std::string::npos);
    }
}

TEST(ShaderSource, IncludeCycleIsAnError) {
    fs::path dir = test::tempDir("cycle");
    test::writeFile(dir / "a.glsl", "#include \"b.glsl\"\n");
    test::writeFile(dir / "b.glsl", "#include \"a.glsl\"\n");
    ShaderLibrary lib({}, {dir}, test::root());
    try {
        lib.assemble("a.glsl", {});
        FAIL() << "no error";
    } catch (const ShaderError& e) {
        EXPECT_NE(std::string(e.what()).find("#include cycle"), std::string::npos) << e.what();
    }
}

TEST(ShaderSource, VersionLineIsOwnedByTheFrameworkAndLinesAreKept) {
    fs::path dir = test::tempDir("version");
    test::writeFile(dir / "x.glsl", "#version 330\nfloat f;\n");
    ShaderLibrary lib({}, {dir}, test::root());
    AssembledShader s = lib.assemble("x.glsl", {"SL_A", "SL_B=2"});
    // One source string, no #line: the line table maps assembled line 5 to x.glsl:2.
    EXPECT_EQ(s.text, "#version 450 core\n#define SL_A\n#define SL_B 2\n\nfloat f;\n") << s.text;
    EXPECT_EQ(s.mapLog("0:5(7): error: oops\n"), lib.displayPath(dir / "x.glsl") + ":2:7: error: oops\n");
    // The driver's source number is ignored (Mesa reports 0 for semantic errors).
    EXPECT_EQ(s.mapLog("3:5(7): error: oops\n"), lib.displayPath(dir / "x.glsl") + ":2:7: error: oops\n");
}

}  // namespace sl
