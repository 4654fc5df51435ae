// Hostile input (a broken file costs only the scenes that use it): #include respects #if/#ifdef.
// lighting.frag includes sat_lookup.glsl under #ifdef SL_FILTER_SAT; expanded line by line, a
// Gaussian scene compiled the SAT lookup too, and a broken sat_lookup.glsl cost `final` on scenes
// that use no SAT.
#include "test_grader_support.h"

#include "glsl_scan.h"
#include "shader_source.h"
#include "technique.h"

namespace sl {
namespace {

bool has(const AssembledShader& s, const std::string& text) {
    return s.text.find(text) != std::string::npos;
}

}  // namespace

TEST(HostileConditionalIncludes, LightingIncludesTheSatLookupOnlyForSatScenes) {
    fs::path dir = test::tempDir("cond_lighting");
    for (const auto& name : stageFileNames())
        fs::copy_file(test::root() / "reference" / name, dir / name);
    test::writeFile(dir / "sat_lookup.glsl", "this file does not compile; // MARKER\n");
    ShaderLibrary lib = ShaderLibrary::forSolution(dir, test::root());
    // msm4's permutation as the renderer builds it, with a Gaussian and with a SAT.
    ShadowEffect fx;
    fx.technique = techniqueFromName("msm4");
    fx.filter = FilterKind::Gaussian;
    EXPECT_FALSE(has(lib.assemble("lighting.frag", techniqueDefines(fx)), "MARKER"));
    fx.filter = FilterKind::Sat;
    EXPECT_TRUE(has(lib.assemble("lighting.frag", techniqueDefines(fx)), "MARKER"));
}

TEST(HostileConditionalIncludes, ConditionsAreEvaluatedWithTheProgramsDefines) {
    fs::path dir = test::tempDir("cond_eval");
    for (const char* f : {"a", "b", "c", "d", "e", "f"})
        test::writeFile(dir / (std::string(f) + ".glsl"), std::string("// FILE_") + f + "\n");
    test::writeFile(dir / "main.glsl",
                    "#define LEVEL 2\n"
                    "#if defined(SL_X) && LEVEL > 1\n#include \"a.glsl\"\n"   // SL_X only
                    "#elif SL_N == 3\n#include \"b.glsl\"\n"                  // SL_N=3 without SL_X
                    "#else\n#include \"c.glsl\"\n#endif\n"
                    "#ifndef SL_X\n  #  include \"d.glsl\" // a comment\n#endif\n"
                    "/*\n#include \"e.glsl\"\n*/\n"                           // in a comment: never
                    "#if SOME_MACRO(1)\n#include \"f.glsl\"\n#endif\n");      // unknown: expanded
    ShaderLibrary lib({}, {dir}, dir);
    auto x = lib.assemble("main.glsl", {"SL_X"});
    EXPECT_TRUE(has(x, "FILE_a"));
    EXPECT_FALSE(has(x, "FILE_b") || has(x, "FILE_c") || has(x, "FILE_d") || has(x, "FILE_e"));
    auto n = lib.assemble("main.glsl", {"SL_N=3"});
    EXPECT_TRUE(has(n, "FILE_b") && has(n, "FILE_d"));
    EXPECT_FALSE(has(n, "FILE_a") || has(n, "FILE_c"));
    auto none = lib.assemble("main.glsl", {});
    EXPECT_TRUE(has(none, "FILE_c") && has(none, "FILE_d") && has(none, "FILE_f"));
    // Lines keep their places: the text after the includes maps to main.glsl's own lines.
    EXPECT_EQ(none.mapLog("0:" + std::to_string(none.lines.size()) + "(1): error: x\n"),
              "main.glsl:17:1: error: x\n");
}

TEST(HostileConditionalIncludes, ABrokenSatLookupCostsNothingOnAGaussianScene) {
    auto sub = test::makeSubmission("broken_sat_lookup",
                                    {{"sat_lookup.glsl", "vec4 satBoxAverage( this is broken\n"}});
    auto g = test::grade("--scenes classic --no-report --submission " + sub.string(),
                         test::tempDir("cond_broken_out"));
    ASSERT_EQ(g.run.exitCode, 0) << g.run.output;
    EXPECT_TRUE(g.full("classic", "final")) << g.output("classic", "final");
    EXPECT_TRUE(g.full("classic", "msm")) << g.output("classic", "msm");
}

}  // namespace sl
