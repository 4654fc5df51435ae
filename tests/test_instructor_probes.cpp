// Scene probes (an instructor checks a scene by hand): `shadowlab project` finds the pixel and the
// light's verdict of a world point, checked against every public probe (whose pixels and values the
// scenes' authors worked out by hand, docs/scenes.md); and a probe that does not hold on the
// reference render is an error in `golden` (naming the file, the probe and the values, writing
// nothing) and in `grade` (which then does not grade on that scene).
#include "test_grader_support.h"

#include <regex>

namespace sl {
namespace {

struct Probe {
    std::string camera;
    int x, y;
    double shadow;
    std::string point;  // "x,y,z", the first world point of the probe's "why"
};

std::vector<Probe> probesOf(const fs::path& scene) {
    const auto j = nlohmann::json::parse(std::ifstream(scene));
    const std::string first = j.contains("cameras") ? j["cameras"][0]["name"].get<std::string>() : "main";
    std::vector<Probe> out;
    if (!j.contains("expect")) return out;
    const std::regex triple(R"(\((-?[0-9.]+), (-?[0-9.]+), (-?[0-9.]+)\))");
    for (const auto& p : j["expect"]["probes"]) {
        std::smatch m;
        const std::string why = p["why"];
        if (!std::regex_search(why, m, triple)) continue;
        out.push_back({p.value("camera", first), p["pixel"][0], p["pixel"][1], p["shadow"],
                       m[1].str() + "," + m[2].str() + "," + m[3].str()});
    }
    return out;
}

}  // namespace

TEST(InstructorProbes, ProjectFindsEveryPublicProbesPixelAndVerdict) {
    int checked = 0;
    for (const auto& entry : fs::directory_iterator(test::root() / "scenes")) {
        if (entry.path().extension() != ".json") continue;
        const auto probes = probesOf(entry.path());
        if (probes.empty()) continue;
        std::string args;
        for (const auto& p : probes) args += " --point=" + p.point;
        auto r = test::runCommand(test::shadowlabBinary() + " project --scene " +
                                  entry.path().string() + args);
        ASSERT_EQ(r.exitCode, 0) << r.output;
        // One block per point, in order, each starting with "<scene>, world point (...)".
        std::vector<std::string> blocks;
        for (size_t at = r.output.find(", world point ("); at != std::string::npos;) {
            const size_t next = r.output.find(", world point (", at + 1);
            blocks.push_back(r.output.substr(at, next == std::string::npos ? next : next - at));
            at = next;
        }
        ASSERT_EQ(blocks.size(), probes.size()) << r.output;
        for (size_t i = 0; i < probes.size(); ++i) {
            const Probe& p = probes[i];
            const std::string where = entry.path().filename().string() + " point " + p.point;
            const std::string pixel = "camera \"" + p.camera + "\" (";
            const size_t c = blocks[i].find(pixel);
            ASSERT_NE(c, std::string::npos) << where << "\n" << blocks[i];
            const std::string expect = "pixel (" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")";
            EXPECT_EQ(blocks[i].find("pixel (", c), blocks[i].find(expect, c)) << where << "\n" << blocks[i];
            EXPECT_NE(blocks[i].find(expect, c), std::string::npos) << where << "\n" << blocks[i];
            // The verdict: a shadowed probe (G = 1) is shadowed with every footprint texel
            // occluded; a lit one (G = 0) sees nothing in front.
            const std::string verdict = p.shadow > 0.5 ? "G = 1" : "G = 0";
            EXPECT_NE(blocks[i].find(verdict), std::string::npos) << where << "\n" << blocks[i];
            EXPECT_NE(blocks[i].find(p.shadow > 0.5 ? "shadowed: " : "lit: "), std::string::npos)
                << where << "\n" << blocks[i];
            ++checked;
        }
    }
    EXPECT_GE(checked, 20);
}

TEST(InstructorProbes, ProjectRejectsAMalformedPoint) {
    auto r = test::runCommand(test::shadowlabBinary() + " project --scene " +
                              test::scenePath("classic").string() + " --point 1,2");
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.output.find("x,y,z"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("\"1,2\""), std::string::npos) << r.output;
}

namespace {

// classic.json with its first probe (G = 1, deep in the sphere's umbra) claiming G = 0.
fs::path wrongProbeScene(const fs::path& dir) {
    auto j = nlohmann::json::parse(std::ifstream(test::scenePath("classic")));
    EXPECT_EQ(j["expect"]["probes"][0]["shadow"].get<double>(), 1.0);
    j["expect"]["probes"][0]["shadow"] = 0.0;
    fs::create_directories(dir);
    const fs::path scene = dir / "classic_wrong_probe.json";
    std::ofstream(scene) << j.dump(2);
    return scene;
}

}  // namespace

TEST(InstructorProbes, GoldenRefusesASceneWhoseProbeTheReferenceContradicts) {
    const fs::path dir = test::tempDir("instructor_wrong_probe_golden");
    const fs::path scene = wrongProbeScene(dir / "private");
    auto r = test::runCommand(test::shadowlabBinary() + " golden --scenes " + scene.string() +
                              " --out " + (dir / "public").string());
    EXPECT_EQ(r.exitCode, 2) << r.output;  // a scene error
    EXPECT_NE(r.output.find(scene.string() + ": /expect/probes/0: expected G = 0"), std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("pixel (88, 294) of camera \"main\""), std::string::npos) << r.output;
    const std::regex renders("the reference renders (0\\.9[0-9]*|1\\.0*)");
    EXPECT_TRUE(std::regex_search(r.output, renders)) << r.output;
    EXPECT_NE(r.output.find("nothing was written"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(dir / "private" / "goldens"));
    EXPECT_FALSE(fs::exists(dir / "public"));
}

TEST(InstructorProbes, GradeStopsOnAHiddenSceneWhoseProbeTheReferenceContradicts) {
    const fs::path dir = test::tempDir("instructor_wrong_probe_grade");
    const fs::path scene = wrongProbeScene(dir / "private");
    auto g = test::grade("--reference live --no-report --scenes " + scene.string() +
                             " --submission " + (test::root() / "reference").string(),
                         dir / "out");
    EXPECT_EQ(g.run.exitCode, 1) << g.run.output;
    ASSERT_TRUE(g.results.is_object()) << g.run.output;
    EXPECT_EQ(g.results["score"].get<double>(), 0.0);
    const std::string output = g.results["output"].get<std::string>();
    EXPECT_NE(output.find("probe"), std::string::npos) << output;
    EXPECT_NE(output.find("golden --check --scenes"), std::string::npos) << output;
    // A hidden scene: its name and file stay out of what the student sees.
    EXPECT_EQ(output.find("classic_wrong_probe"), std::string::npos) << output;
}

}  // namespace sl

namespace sl {

TEST(InstructorProbes, RenderChecksTheProbesOfTheReference) {
    const fs::path dir = test::tempDir("instructor_wrong_probe_render");
    auto ok = test::runCommand(test::shadowlabBinary() + " render --scene " +
                               test::scenePath("classic").string() + " --out " + (dir / "ok").string());
    ASSERT_EQ(ok.exitCode, 0) << ok.output;
    EXPECT_NE(ok.output.find("probes: all 4 hold"), std::string::npos) << ok.output;
    const fs::path scene = wrongProbeScene(dir / "private");
    auto bad = test::runCommand(test::shadowlabBinary() + " render --scene " + scene.string() +
                                " --out " + (dir / "bad").string());
    EXPECT_EQ(bad.exitCode, 2) << bad.output;
    EXPECT_NE(bad.output.find(scene.string() + ": /expect/probes/0: expected G = 0"), std::string::npos)
        << bad.output;
    EXPECT_TRUE(fs::exists(dir / "bad" / "shadow.exr"));  // written, to look at
}

// Another solution's render only hears about the probes, in notes that name that solution and
// its value (a G inverted from the reference's moments: 0 in the umbra), not the reference. A
// render with a stub stage gets no probe notes: the stub's -1 would read as a wrong probe.
TEST(InstructorProbes, RenderOfAnotherSolutionNamesItInTheProbeNotes) {
    const fs::path dir = test::tempDir("instructor_probe_notes");
    const fs::path solution = dir / "g_inverted";
    fs::create_directories(solution);
    for (const auto& e : fs::directory_iterator(test::root() / "reference"))
        fs::copy_file(e.path(), solution / e.path().filename());
    fs::copy_file(test::root() / "tests/submissions/mutants/msm_g_inverted/msm.glsl", solution / "msm.glsl",
                  fs::copy_options::overwrite_existing);
    auto r = test::runCommand(test::shadowlabBinary() + " render --solution " + solution.string() +
                              " --scene " + test::scenePath("classic").string() + " --out " + (dir / "out").string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("note: probe: "), std::string::npos) << r.output;
    EXPECT_TRUE(std::regex_search(r.output, std::regex("of camera \"main\", " + solution.string() +
                                                       " renders 0\\.00[0-9]+ \\(off by (1|0\\.99[0-9])\\)")))
        << r.output;
    EXPECT_EQ(r.output.find("the reference renders"), std::string::npos) << r.output;

    auto stubs = test::runCommand(test::shadowlabBinary() + " render --solution student --scene " +
                                  test::scenePath("classic").string() + " --out " + (dir / "stubs").string());
    ASSERT_EQ(stubs.exitCode, 0) << stubs.output;
    EXPECT_NE(stubs.output.find("probes: not checked while a stage is a stub"), std::string::npos) << stubs.output;
    EXPECT_EQ(stubs.output.find("note: probe: "), std::string::npos) << stubs.output;
}

}  // namespace sl
