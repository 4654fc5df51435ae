// A batch that survives (batch_store.h, gradebook.h): each submission's row is stored under the
// digest of its folder and of the setup as it ends; a batch killed at any point and started
// again grades only what is missing and writes the same scores.csv; a changed folder is graded
// again; shards of a batch merged give the one-process gradebook; the gradebook's pages open.
#include "test_grader_support.h"

#include "batch_store.h"
#include "gradebook.h"

#include <chrono>
#include <csignal>
#include <thread>

#include <sys/wait.h>
#include <unistd.h>

namespace sl {
namespace {

// Four students: two correct, the stub kit, and one whose msm.glsl drops its final clamp.
fs::path classFolder(const std::string& name) {
    const fs::path dir = test::tempDir(name);
    fs::copy(test::root() / "reference", dir / "alice");
    fs::copy(test::root() / "student", dir / "bob");
    fs::copy(test::root() / "reference", dir / "carol");
    fs::copy(test::root() / "reference", dir / "dave");
    std::string msm = test::readFile(test::root() / "reference" / "msm.glsl");
    std::ofstream(dir / "dave" / "msm.glsl") << msm << "\n// dave's own comment\n";
    return dir;
}

test::CommandResult batch(const fs::path& in, const fs::path& out, const std::string& extra = "") {
    return test::runCommand(test::shadowlabBinary() + " grade --batch " + in.string() +
                            " -j 2 --scenes classic --no-report --out " + out.string() + " " + extra);
}

}  // namespace

TEST(BatchStore, TheDigestFollowsTheFolderBytesAndNamesOnly) {
    const fs::path a = test::tempDir("digest_a");
    std::ofstream(a / "msm.glsl") << "void main() {}\n";
    const std::string d0 = grader::submissionDigest(a);
    EXPECT_EQ(grader::submissionDigest(a), d0);
    std::ofstream(a / "msm.glsl") << "void main() { }\n";  // one byte more
    const std::string d1 = grader::submissionDigest(a);
    EXPECT_NE(d1, d0);
    fs::rename(a / "msm.glsl", a / "moments.glsl");  // same bytes, another name
    EXPECT_NE(grader::submissionDigest(a), d1);
    fs::rename(a / "moments.glsl", a / "msm.glsl");
    EXPECT_EQ(grader::submissionDigest(a), d1);
    fs::create_directories(a / "notes");
    std::ofstream(a / "notes" / "todo.txt") << "x";
    EXPECT_NE(grader::submissionDigest(a), d1);  // every file counts
    EXPECT_NE(grader::rowDigest(d1, "setup A"), grader::rowDigest(d1, "setup B"));
}

TEST(Gradebook, OneRowPerStudentAndNoZeroForOneNotGraded) {
    grader::BatchRow r;
    r.score = 93.75, r.maxScore = 100;
    r.stagePoints = {{"moments", 18.75}, {"msm", 18.75}};
    r.stageMax = {{"moments", 18.75}, {"msm", 25}};
    r.lost = {"classic msm -6.25"};
    r.notes = {"a note, with a comma"};
    const std::string csv = grader::scoresCsv({{"smith, j", r}, {"lee", std::nullopt}});
    EXPECT_EQ(csv.substr(0, csv.find('\n')),
              "student,total,max,moments,gaussian,sat,msm,robustness,final,lost,notes");
    EXPECT_NE(csv.find("\n\"smith, j\",93.75,100.00,18.75,,,18.75,,,classic msm -6.25,\"a note, with a comma\"\n"),
              std::string::npos) << csv;
    EXPECT_NE(csv.find("\nlee,,,,,,,,,,not graded\n"), std::string::npos) << csv;
    const std::string page = grader::classPage({{"smith, j", r}, {"lee", std::nullopt}});
    EXPECT_NE(page.find("1 graded, 0 the grader could not grade, 1 not graded yet"), std::string::npos);
    EXPECT_NE(page.find("<td>classic msm</td><td>1</td><td>6.25</td>"), std::string::npos) << page;
    const std::string index = grader::indexPage({{"smith, j", r}});
    EXPECT_NE(index.find("href=\"smith%2C%20j/results.json\""), std::string::npos) << index;
}

TEST(BatchResume, AKilledBatchGradesOnlyWhatIsMissingAndGivesTheSameScores) {
    const fs::path in = classFolder("resume_in");
    const fs::path once = test::tempDir("resume_once");
    const auto first = batch(in, once);
    ASSERT_EQ(first.exitCode, 0) << first.output;
    const std::string csv = test::readFile(once / "scores.csv");
    EXPECT_NE(csv.find("\nalice,100.00,100.00,"), std::string::npos) << csv;
    EXPECT_NE(csv.find("\nbob,0.00,100.00,0.00,"), std::string::npos) << csv;
    EXPECT_NE(csv.find("classic moments -18.75"), std::string::npos) << csv;  // bob's lost tests

    // Killed (SIGKILL, no chance to tidy up) once the first row is stored.
    const fs::path killed = test::tempDir("resume_killed");
    const pid_t pid = ::fork();
    if (pid == 0) {
        ::execl("/bin/sh", "sh", "-c",
                ("exec " + test::shadowlabBinary() + " grade --batch " + in.string() +
                 " -j 1 --scenes classic --no-report --out " + killed.string() + " > /dev/null 2>&1").c_str(),
                (char*)nullptr);
        ::_exit(127);
    }
    const auto start = std::chrono::steady_clock::now();
    auto rows = [&] {
        int n = 0;
        for (const char* who : {"alice", "bob", "carol", "dave"}) n += fs::exists(killed / who / "row.json");
        return n;
    };
    while (rows() == 0 && std::chrono::steady_clock::now() - start < std::chrono::seconds(120))
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    ::kill(pid, SIGKILL);
    int status = 0;
    ::waitpid(pid, &status, 0);
    const int before = rows();
    ASSERT_GE(before, 1);
    ASSERT_LT(before, 4) << "the batch ended before it could be killed";
    EXPECT_FALSE(fs::exists(killed / "scores.csv"));

    const auto again = batch(in, killed);
    ASSERT_EQ(again.exitCode, 0) << again.output;
    EXPECT_NE(again.output.find("graded " + std::to_string(4 - before) + ", already graded " +
                                std::to_string(before)), std::string::npos) << again.output;
    EXPECT_EQ(test::readFile(killed / "scores.csv"), csv);

    // A changed folder is graded again, and only that one; a row cut short is graded again.
    std::ofstream(in / "carol" / "moments.glsl", std::ios::app) << "\n// carol, late\n";
    std::ofstream(killed / "alice" / "row.json") << "{\"failed\": fal";
    const auto third = batch(in, killed);
    ASSERT_EQ(third.exitCode, 0) << third.output;
    EXPECT_NE(third.output.find("graded 2, already graded 2"), std::string::npos) << third.output;
    EXPECT_EQ(test::readFile(killed / "scores.csv"), csv);
}

TEST(BatchResume, ShardsMergedGiveTheOneProcessGradebook) {
    const fs::path in = classFolder("shard_in");
    const fs::path once = test::tempDir("shard_once");
    ASSERT_EQ(batch(in, once).exitCode, 0);
    const fs::path out = test::tempDir("shard_out");
    const auto one = batch(in, out, "--shard 1/2");
    ASSERT_EQ(one.exitCode, 0) << one.output;
    EXPECT_NE(one.output.find("shard 1/2: graded 2, already graded 0"), std::string::npos) << one.output;
    EXPECT_FALSE(fs::exists(out / "scores.csv"));  // the merge writes it
    // A merge before every shard has run lists who is missing and fails; no zero for them.
    const auto early = batch(in, out, "--merge");
    EXPECT_NE(early.exitCode, 0);
    EXPECT_NE(early.output.find("2 not graded yet: bob dave"), std::string::npos) << early.output;
    EXPECT_NE(test::readFile(out / "scores.csv").find("\nbob,,,"), std::string::npos);
    ASSERT_EQ(batch(in, out, "--shard 2/2").exitCode, 0);
    const auto merged = batch(in, out, "--merge");
    ASSERT_EQ(merged.exitCode, 0) << merged.output;
    EXPECT_NE(merged.output.find("graded 0, already graded 4"), std::string::npos) << merged.output;
    EXPECT_EQ(test::readFile(out / "scores.csv"), test::readFile(once / "scores.csv"));
    EXPECT_EQ(test::readFile(out / "class.html"), test::readFile(once / "class.html"));
}

TEST(Gradebook, TheIndexLinksEveryReportAndTheClassPageShowsItsCharts) {
    const fs::path in = test::tempDir("gradebook_in");
    fs::copy(test::root() / "reference", in / "alice");
    fs::copy(test::root() / "student", in / "bob");
    const fs::path out = test::tempDir("gradebook_out");
    const auto r = test::runCommand(test::shadowlabBinary() + " grade --batch " + in.string() +
                                    " -j 2 --scenes classic --out " + out.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const std::string index = test::readFile(out / "index.html");
    for (const char* who : {"alice", "bob"}) {
        EXPECT_NE(index.find(std::string("href=\"") + who + "/report/index.html\""), std::string::npos) << index;
        EXPECT_TRUE(fs::exists(out / who / "report" / "index.html"));
    }
    const std::string page = test::readFile(out / "class.html");
    EXPECT_NE(page.find("<figcaption>msm (2)</figcaption><svg"), std::string::npos) << page;
    EXPECT_NE(page.find("<td>classic msm</td><td>1</td><td>25.00</td>"), std::string::npos) << page;
    if (test::runCommand("command -v chromium").exitCode != 0)
        GTEST_SKIP() << "chromium is not installed (apt-get install chromium): the page is not opened";
    const fs::path shot = test::tempDir("gradebook_shot") / "class.png";
    const auto s = test::screenshotPage(out / "class.html", shot, test::tempDir("gradebook_profile"), 1000, 800);
    ASSERT_TRUE(fs::exists(shot)) << s.output;
    EXPECT_GT(test::colourSpread(shot), 0.05) << "the screenshot is (nearly) one colour: a blank page";
}

}  // namespace sl
