// Hostile input (the grader writes only under its output folder): the grader's output folder.
// `--out` equal to the submission deleted the student's report/ folder; a results.json.tmp link
// there was followed (an arbitrary file write); `--out scenes/` broke every later grade. OUT may
// not be, contain or lie inside the submission, scenes/, reference/ or the goldens; files are
// written through fresh O_EXCL | O_NOFOLLOW temp files; an OUT that is a file is a clear error.
#include "test_grader_support.h"

namespace sl {
namespace {

test::CommandResult gradeInto(const fs::path& sub, const std::string& out) {
    return test::runCommand(test::shadowlabBinary() + " grade --scenes classic --no-report "
                            "--submission " + sub.string() + " --out " + out);
}

}  // namespace

TEST(HostileOutFolder, AnOutThatTouchesTheSubmissionOrTheKitIsRefused) {
    auto sub = test::makeSubmission("out_guard");
    fs::create_directories(sub / "report");
    std::ofstream(sub / "report" / "mine.txt") << "the student's own notes\n";
    const fs::path victim = test::tempDir("out_guard_victim") / "victim.txt";
    std::ofstream(victim) << "untouched\n";
    fs::create_symlink(victim, sub / "results.json.tmp");
    const fs::path file = test::tempDir("out_guard_file") / "a_file";
    std::ofstream(file) << "x\n";
    const fs::path root = test::root();
    const std::vector<std::pair<std::string, std::string>> cases = {
        {sub.string(), "is"},
        {(sub / "report").string(), "lies inside"},
        {sub.parent_path().string(), "contains"},
        {(root / "scenes").string(), "is"},
        {(root / "scenes" / "goldens" / "x").string(), "lies inside"},
        {(root / "reference").string(), "is"},
        {root.string(), "contains"},
        {file.string(), "not a folder"}};
    for (const auto& [out, why] : cases) {
        SCOPED_TRACE(out);
        const auto r = gradeInto(sub, out);
        EXPECT_EQ(r.exitCode, 2) << r.output;
        EXPECT_NE(r.output.find("error: --out " + out), std::string::npos) << r.output;
        EXPECT_NE(r.output.find(why), std::string::npos) << r.output;
        EXPECT_EQ(r.output.find("results:"), std::string::npos) << "no results path:\n" << r.output;
    }
    EXPECT_EQ(test::readFile(sub / "report" / "mine.txt"), "the student's own notes\n");
    EXPECT_EQ(test::readFile(victim), "untouched\n");
    EXPECT_FALSE(fs::exists(root / "scenes" / "results.json"));
    EXPECT_FALSE(fs::exists(root / "scenes" / "goldens" / "x"));
}

TEST(HostileOutFolder, ALinkPlantedInOutIsReplacedNotFollowed) {
    auto sub = test::makeSubmission("out_link", {}, {"moments.glsl", "gaussian_blur.comp", "sat.comp",
                                                     "sat_lookup.glsl", "msm.glsl"});
    const fs::path out = test::tempDir("out_link_out");
    const fs::path victim = test::tempDir("out_link_victim") / "victim.txt";
    std::ofstream(victim) << "untouched\n";
    fs::create_symlink(victim, out / "results.json.tmp");
    fs::create_symlink(victim, out / "results.json");
    const auto r = gradeInto(sub, out.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(test::readFile(victim), "untouched\n");
    EXPECT_FALSE(fs::is_symlink(out / "results.json"));
    EXPECT_NE(test::readFile(out / "results.json").find("\"tests\""), std::string::npos);
}

}  // namespace sl
