// The Gradescope autograder (it must install and grade on Gradescope unattended): `shadowlab
// package --kind gradescope` unzipped into an /autograder-shaped folder ($SHADOWLAB_AUTOGRADER
// replaces /autograder), setup.sh installs only the autograder's packages and builds,
// run_autograder grades a correct submission to full marks. Slow: a build of the kit (ccache hits
// when this build used it).
#include "kit_test_support.h"

#include <nlohmann/json.hpp>

namespace sl {

TEST(KitGradescope, GraderPackagesLeaveOutWhatGradingNeverUses) {
    const std::string kit = test::readFile(test::root() / "kit");
    std::smatch m;
    ASSERT_TRUE(std::regex_search(kit, m, std::regex(R"(GRADER_PACKAGES=\(([^)]*)\))")));
    const std::string list = " " + std::regex_replace(m[1].str(), std::regex(R"(\s+)"), " ") + " ";
    for (const char* p : {" chromium ", " xvfb ", " libgtest-dev ", " gnuplot-nox "})
        EXPECT_EQ(list.find(p), std::string::npos) << p;
    for (const char* p : {" libosmesa6 ", " libopenimageio-dev ", " cmake "})
        EXPECT_NE(list.find(p), std::string::npos) << p;
}

TEST(KitGradescope, SetupAndRunAutograderGradeACorrectSubmissionToFullMarks) {
    const fs::path dir = test::tempDir("gradescope");
    const fs::path zip = dir / "autograder.zip", ag = dir / "autograder";
    auto pack = test::runCommand(test::shadowlabBinary() + " package --kind gradescope --out " + zip.string());
    ASSERT_EQ(pack.exitCode, 0) << pack.output;
    fs::create_directories(ag / "submission");
    ASSERT_EQ(test::runCommand("unzip -q '" + zip.string() + "' -d '" + ag.string() + "'").exitCode, 0);
    ASSERT_TRUE(fs::exists(ag / "setup.sh") && fs::exists(ag / "run_autograder"));
    EXPECT_NE(test::readFile(ag / "setup.sh").find("./kit deps --grader"), std::string::npos);
    // The yardstick of ./kit check: the committed goldens, hidden scenes' included.
    EXPECT_NE(test::readFile(ag / "run_autograder").find("--reference golden"), std::string::npos);
    for (const auto& name : stageFileNames())
        fs::copy_file(test::root() / "reference" / name, ag / "submission" / name);

    const std::string env = "env -u SHADOWLAB_ROOT SHADOWLAB_AUTOGRADER='" + ag.string() + "'";
    auto setup = test::runIn(dir, "bash autograder/setup.sh", 900, env);
    ASSERT_EQ(setup.exitCode, 0) << setup.output;
    EXPECT_TRUE(fs::exists(ag / "source/build/shadowlab"));
    EXPECT_FALSE(fs::exists(ag / "source/build/tests")) << "the autograder builds no tests";

    auto run = test::runIn(dir, "bash autograder/run_autograder", 600, env);
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const auto results = nlohmann::json::parse(std::ifstream(ag / "results/results.json"));
    double max = 0;
    for (const auto& t : results["tests"]) max += t["max_score"].get<double>();
    EXPECT_GT(max, 0);
    EXPECT_NEAR(results["score"].get<double>(), max, 1e-9) << results.dump(1).substr(0, 4000);
    EXPECT_NE(run.output.find("kit root: " + fs::weakly_canonical(ag / "source").string()), std::string::npos)
        << run.output;
}

}  // namespace sl
