// Hostile input: no text a student submits crashes the grader. std::regex on
// a 40 000-space line or `#include "` + 30 000 characters overflowed the stack (SIGSEGV in the
// grading process, no results.json). The source path is scanned by hand now; this fuzzes it
// in-process (random bytes, NULs, long lines, deep and cyclic includes, huge files, #if
// expressions nested deep) and grades the worst files end to end.
#include "test_grader_support.h"

#include "glsl_scan.h"
#include "shader_source.h"

#include <random>

namespace sl {
namespace {

// Assembling either works or throws ShaderError with a message; nothing else.
void assembleSurvives(const ShaderLibrary& lib, const std::string& file,
                      const std::vector<std::string>& defines = {}) {
    try {
        AssembledShader s = lib.assemble(file, defines);
        EXPECT_EQ(s.lines.size(), size_t(std::count(s.text.begin(), s.text.end(), '\n')));
        (void)s.mapLog("0:" + std::to_string(s.lines.size() + 5) + "(1): error: x\n");
    } catch (const ShaderError& e) {
        EXPECT_FALSE(std::string(e.what()).empty());
    }
}

std::string randomText(std::mt19937& rng, size_t size) {
    // Bytes biased towards what the scanner looks at.
    static const std::string alphabet = "#\"/*\\\n\r\t ()<>!&|=+-includefvrsioA1_";
    std::string s(size, ' ');
    for (char& c : s)
        c = rng() % 4 == 0 ? char(rng() % 256) : alphabet[rng() % alphabet.size()];
    return s;
}

}  // namespace

TEST(HostileSourceFuzz, RandomAndPathologicalSourcesNeverCrashTheAssembler) {
    const fs::path dir = test::tempDir("fuzz_source");
    std::mt19937 rng(7);
    ShaderLibrary lib({}, {dir}, dir);
    for (int i = 0; i < 300; ++i) {
        test::writeFile(dir / "a.glsl", randomText(rng, rng() % 4000));
        test::writeFile(dir / "b.glsl", "#include \"a.glsl\"\n" + randomText(rng, rng() % 2000));
        assembleSurvives(lib, "b.glsl", {"SL_X", "SL_N=3"});
    }
    const std::vector<std::string> worst = {
        std::string(40000, ' ') + "\n",
        "#include \"" + std::string(30000, 'x') + "\n",
        "#include \"" + std::string(30000, 'x') + "\"\n",
        "// " + std::string(60000, 'c') + "\n",
        "/*" + std::string(60000, '*'),
        std::string(1000, '\0') + "\n#include \"a.glsl\"\n",
        "#if " + std::string(40000, '(') + "1\n#include \"a.glsl\"\n#endif\n",
        "#if " + std::string(40000, '!') + "1\n#endif\n",
        "#define A A\n#if A\n#endif\n#define B (B + B)\n#if B\n#endif\n",
        "#define X 1\n#if " + [] { std::string s; for (int i = 0; i < 20000; ++i) s += "X+"; return s + "X"; }() + "\n#endif\n",
        "#if 1/0\n#endif\n#if 0x\n#endif\n#if 99999999999999999999999\n#endif\n#if 1 << 99\n#endif\n",
        std::string(20000, '#') + "\n",
        "#" + std::string(30000, 'i') + "\n",
        std::string(100000, '\n'),
    };
    for (const auto& text : worst) {
        test::writeFile(dir / "w.glsl", text);
        test::writeFile(dir / "a.glsl", "float a;\n");
        assembleSurvives(lib, "w.glsl");
    }
}

TEST(HostileSourceFuzz, DeepCyclicAndHugeIncludesAreErrors) {
    const fs::path dir = test::tempDir("fuzz_includes");
    ShaderLibrary lib({}, {dir}, dir);
    auto message = [&](const std::string& file) -> std::string {
        try {
            lib.assemble(file, {});
        } catch (const ShaderError& e) {
            return e.what();
        }
        return "";
    };
    for (int i = 0; i < 40; ++i)
        test::writeFile(dir / ("d" + std::to_string(i) + ".glsl"), "#include \"d" + std::to_string(i + 1) + ".glsl\"\n");
    test::writeFile(dir / "d40.glsl", "float deep;\n");
    EXPECT_NE(message("d0.glsl").find("nested more than 32 deep"), std::string::npos) << message("d0.glsl");
    test::writeFile(dir / "self.glsl", "#include \"self.glsl\"\n");
    EXPECT_NE(message("self.glsl").find("#include cycle"), std::string::npos);
    test::writeFile(dir / "huge.glsl", std::string(17u << 20, 'x'));
    test::writeFile(dir / "big.glsl", "#include \"huge.glsl\"\n");
    EXPECT_NE(message("big.glsl").find("over 16 MiB"), std::string::npos);
}

TEST(HostileSourceFuzz, DriverLogsOfAnyShapeAreMappedWithoutRegex) {
    AssembledShader s;
    s.text = "#version 450 core\nx\n";
    s.fileNames = {"submission/msm.glsl"};
    s.lines = {{-1, 0}, {0, 7}};
    EXPECT_EQ(s.mapLog("0:2(3): error: e\n"), "submission/msm.glsl:7:3: error: e\n");
    EXPECT_EQ(s.mapLog("ERROR: 0:2: e\n"), "submission/msm.glsl:7: e\n");
    std::mt19937 rng(11);
    for (int i = 0; i < 200; ++i) {
        std::string log = "0:" + std::string(rng() % 60000, '9') + "(" +
                          std::string(rng() % 100, '1') + "): " + randomText(rng, rng() % 60000);
        (void)s.mapLog(log);
    }
    (void)s.mapLog(std::string(100000, ':'));
}

TEST(HostileSourceFuzz, TheWorstFilesAreGradedWithResultsWritten) {
    const std::string moments = test::readFile(test::root() / "reference" / "moments.glsl");
    const std::string sat = test::readFile(test::root() / "reference" / "sat.comp");
    std::mt19937 rng(3);
    auto sub = test::makeSubmission(
        "fuzz_worst", {{"moments.glsl", moments + std::string(40000, ' ') + "\n"},
                       {"msm.glsl", "#include \"" + std::string(30000, 'x') + "\n"},
                       {"gaussian_blur.comp", randomText(rng, 30000) + std::string(1, '\0')},
                       {"sat.comp", sat + "// " + std::string(60000, 'c') + "\n"}});
    test::writeFile(sub / "deep.glsl", "#include \"deep.glsl\"\n" + randomText(rng, 5000));
    auto g = test::grade("--scenes contact --no-report --submission " + sub.string(),
                         test::tempDir("fuzz_worst_out"));
    ASSERT_EQ(g.run.exitCode, 0) << g.run.output;
    ASSERT_TRUE(g.results.contains("tests")) << g.run.output;
    EXPECT_TRUE(g.full("contact", "moments")) << g.output("contact", "moments");
    EXPECT_TRUE(g.full("contact", "sat")) << g.output("contact", "sat");
    EXPECT_NE(g.output("contact", "msm").find("msm.glsl: refused: line 1: #include"), std::string::npos)
        << g.output("contact", "msm");
}

}  // namespace sl
