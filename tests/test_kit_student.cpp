// The student kit as a student gets it (it must build and run as shipped and hold no solution):
// `shadowlab package --kind student`, unpacked into its `shadowlab/` folder, holds exactly what
// grader/student_kit.manifest names and no solution-bearing file, builds, and runs every command
// line its own README and handout show. (KitAttack.* tries what it holds as stages.) Slow (a build
// of the kit; ccache makes the compiles hits when this build used it): see docs/grading.md for the
// measured time.
#include "kit_test_support.h"
#include "student_kit.h"

#include <algorithm>
#include <chrono>
#include <regex>
#include <set>

namespace sl {
namespace {

std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string l; std::getline(in, l);) out.push_back(l);
    return out;
}

// What no student may get: a solution, its mirrors, the exact solver, the mutants and correct
// alternatives, hidden scenes and their goldens, the log of the reference's measured designs.
// Returns the offending entries.
std::vector<std::string> solutionBearing(const std::vector<std::string>& entries) {
    static const std::regex bad(
        R"(^shadowlab/(reference/|tests/oracles/|tests/submissions/|scenes/hidden/|framework/numerics/msm_exact\.cpp|docs/catalogue\.md|docs/performance_log\.md)|(^|/)goldens/.*hidden)");
    std::vector<std::string> out;
    for (const auto& e : entries)
        if (std::regex_search(e, bad)) out.push_back(e);
    return out;
}

}  // namespace

TEST(KitStudent, SolutionBearingPathsAreRecognised) {
    // The check below must catch each of these (and pass the kit's own files).
    auto found = solutionBearing({"shadowlab/reference/msm.glsl", "shadowlab/tests/oracles/x.h",
                                  "shadowlab/tests/submissions/mutants/a/msm.glsl",
                                  "shadowlab/framework/numerics/msm_exact.cpp",
                                  "shadowlab/scenes/hidden/goldens/shelf/final.exr",
                                  "shadowlab/docs/performance_log.md",
                                  "shadowlab/student/msm.glsl", "shadowlab/framework/numerics/msm_exact.h"});
    EXPECT_EQ(found.size(), 6u) << testing::PrintToString(found);
}

// The manifest's format: files and folders, comments, missing entries skipped; nothing outside
// the kit; a folder entry that reaches a path no student kit may hold stops the packing.
TEST(KitStudent, ManifestNamesFilesAndFoldersAndNothingElse) {
    const fs::path root = test::tempDir("student_kit_manifest");
    for (const char* f : {"kit", "docs/a.md", "docs/images/x.png", "shaders/keep.glsl", "shaders/leak.glsl",
                          "reference/msm.glsl"})
        test::writeFile(root / f, "x");
    test::writeFile(root / grader::kStudentKitManifest,
                    "# comment\n\nkit\n  docs/   # a folder\nshaders/keep.glsl\nshaders/gone.glsl\n");
    EXPECT_EQ(grader::studentKitManifest(root),
              (std::vector<std::string>{"kit", "docs", "shaders/keep.glsl", "shaders/gone.glsl"}));
    EXPECT_EQ(grader::studentKitFiles(root),
              (std::vector<std::string>{"docs/a.md", "docs/images/x.png", "kit", "shaders/keep.glsl"}));
    for (const char* bad : {"../outside\n", "/etc/passwd\n", "docs/../../x\n"}) {
        test::writeFile(root / grader::kStudentKitManifest, bad);
        EXPECT_THROW(grader::studentKitManifest(root), std::runtime_error) << bad;
    }
    test::writeFile(root / grader::kStudentKitManifest, "kit\nreference\n");
    EXPECT_THROW(grader::studentKitFiles(root), std::runtime_error);
    fs::remove(root / grader::kStudentKitManifest);
    EXPECT_THROW(grader::studentKitFiles(root), std::runtime_error);
}

// The tests the manifest ships need only what the kit holds: none names the oracles, the exact
// solver or the submissions, and none includes a test file the manifest leaves out (the kit's
// `./kit test` would not compile). The old rule found these by their text; now they are named.
TEST(KitStudent, ManifestTestsNeedOnlyWhatTheKitHolds) {
    const auto files = grader::studentKitFiles(test::root());
    const std::set<std::string> kit(files.begin(), files.end());
    std::vector<std::string> shadowlabPaths;
    for (const auto& f : files) shadowlabPaths.push_back("shadowlab/" + f);
    EXPECT_TRUE(solutionBearing(shadowlabPaths).empty()) << testing::PrintToString(solutionBearing(shadowlabPaths));
    static const std::regex include(R"re(^\s*#\s*include\s+"([^"]+)")re");
    int tests = 0;
    for (const auto& f : files) {
        const fs::path p(f);
        if (p.parent_path() != "tests" || (p.extension() != ".cpp" && p.extension() != ".h")) continue;
        ++tests;
        const std::string text = test::readFile(test::root() / f);
        for (const char* word : {"oracles/", "msm_exact", "submissions"})
            EXPECT_EQ(text.find(word), std::string::npos) << f << " names " << word;
        for (const auto& line : lines(text)) {
            std::smatch m;
            if (!std::regex_search(line, m, include)) continue;
            const std::string inc = m[1].str();
            if (fs::exists(test::root() / "tests" / inc))
                EXPECT_TRUE(kit.count("tests/" + inc)) << f << " includes " << inc << ", which the kit leaves out";
        }
    }
    EXPECT_GT(tests, 20);
    // The two tests that check the kit, and what they compare with, stay out of it.
    for (const char* f : {"tests/test_kit_student.cpp", "tests/test_kit_attack.cpp", "tests/test_grader_support.h"})
        EXPECT_FALSE(kit.count(f)) << f;
}

// The pages a student reads, as the student kit ships them (grader::studentMarkdown), name no
// file, test or command the kit does not have (a file in reference/, the oracles, the
// submissions, a test it leaves out, a --gtest_filter): those lines are instructor blocks
// (saying that a kit may have no reference/ is fine). Quick: no
// kit is built (the test below checks README and handout in a built kit, and runs them).
TEST(KitStudent, StudentDocsNameNothingTheKitLacks) {
    // The test files the manifest leaves out.
    const auto shipped = grader::studentKitFiles(test::root());
    std::vector<std::string> dropped;
    for (const auto& e : fs::directory_iterator(test::root() / "tests"))
        if (e.is_regular_file() &&
            std::find(shipped.begin(), shipped.end(), "tests/" + e.path().filename().string()) ==
                shipped.end())
            dropped.push_back("tests/" + e.path().filename().string());
    for (const char* doc : {"README.md", "docs/handout.md", "docs/numerics.md", "docs/stage_contract.md"}) {
        const std::string text = grader::studentMarkdown(test::readFile(test::root() / doc));
        static const std::regex missing(
            R"((^|[^A-Za-z_/])(reference/[A-Za-z_*]|tests/oracles|tests/submissions|--gtest_filter|shadowlab_tests|catalogue\.md|performance_log\.md))");
        std::smatch m;
        EXPECT_FALSE(std::regex_search(text, m, missing))
                << doc << " (student kit) names " << m[2] << ": ..." << m.suffix().str().substr(0, 120);
        for (const auto& name : dropped)
            EXPECT_EQ(text.find(name), std::string::npos) << doc << " (student kit) names " << name;
    }
    // Every path the student's pages and stubs name is in the kit: a file it ships, or a folder
    // of them (the container files for macOS and Windows, the pass a stub names, ...). Outputs
    // (out/, build/) and patterns (`scenes/goldens/<scene>/`) are not files to ship.
    std::vector<std::string> pages = {"README.md", "docs/handout.md", "docs/stage_contract.md",
                                      "docs/numerics.md", "docs/grading.md", "docs/scenes.md"};
    for (const auto& e : fs::directory_iterator(test::root() / "student"))
        pages.push_back("student/" + e.path().filename().string());
    static const std::regex named(
        R"((^|[^A-Za-z0-9_./-])((docs|scenes|shaders|student|tools|grader|framework|cli|tests|\.devcontainer)/[A-Za-z0-9_./-]*|Dockerfile)([<*{]?))");
    auto ships = [&](std::string path) {
        while (!path.empty() && std::string(".,;:").find(path.back()) != std::string::npos) path.pop_back();
        return std::any_of(shipped.begin(), shipped.end(), [&](const std::string& f) {
            return f == path || (path.back() == '/' && f.rfind(path, 0) == 0) || f.rfind(path + "/", 0) == 0;
        });
    };
    int checked = 0;
    for (const auto& page : pages) {
        std::string text = test::readFile(test::root() / page);
        if (page.ends_with(".md")) text = grader::studentMarkdown(text);
        for (std::sregex_iterator it(text.begin(), text.end(), named), end; it != end; ++it) {
            if (!(*it)[4].str().empty()) continue;  // a pattern: <scene>, *.json, {a,b}
            ++checked;
            EXPECT_TRUE(ships((*it)[2].str())) << page << " (student kit) names " << (*it)[2] << ", which the kit lacks";
        }
    }
    EXPECT_GT(checked, 40);
    // What the framework does with the stage files' preprocessor lines (shader_source.cpp;
    // HostileErrorLines.LineAndExtensionDirectivesAreRefused): #line is refused, not prepended.
    const std::string contract = test::readFile(test::root() / "docs/stage_contract.md");
    EXPECT_NE(contract.find("`#line` and `#extension` are refused"), std::string::npos);
    EXPECT_EQ(contract.find("and a `#line` directive"), std::string::npos);
}

TEST(KitStudent, TarballHasNoSolutionBuildsAndRunsEveryDocumentedCommand) {
    using Clock = std::chrono::steady_clock;
    const auto unpacked = test::unpackStudentKit(test::tempDir("student_kit"));
    ASSERT_EQ(unpacked.error, "");
    const auto& entries = unpacked.entries;
    const fs::path kit = unpacked.root;

    // Contents: one top folder shadowlab/, nothing that bears the solution, and exactly the
    // files the manifest names (plus the exact 4MSM's generated table): a file not named is out.
    ASSERT_GT(entries.size(), 50u);
    for (const auto& e : entries) ASSERT_EQ(e.rfind("shadowlab/", 0), 0u) << e;
    EXPECT_TRUE(solutionBearing(entries).empty()) << testing::PrintToString(solutionBearing(entries));
    std::set<std::string> packed, named;
    for (const auto& e : entries)
        if (e.back() != '/') packed.insert(e.substr(std::string("shadowlab/").size()));
    for (const auto& f : grader::studentKitFiles(test::root())) named.insert(f);
    named.insert("framework/numerics/msm_exact_table.cpp");
    EXPECT_EQ(packed, named);
    // Public goldens only: each golden folder belongs to a public scene of the kit.
    for (const auto& e : fs::directory_iterator(kit / "scenes/goldens"))
        if (e.is_directory())
            EXPECT_TRUE(fs::exists(kit / "scenes" / (e.path().filename().string() + ".json"))) << e.path();
    // No test in the kit needs what the kit lacks.
    for (const auto& e : fs::directory_iterator(kit / "tests")) {
        if (e.path().extension() != ".cpp" && e.path().extension() != ".h") continue;
        const std::string text = test::readFile(e.path());
        EXPECT_EQ(text.find("oracles/"), std::string::npos) << e.path();
        EXPECT_EQ(text.find("submissions"), std::string::npos) << e.path();
    }
    EXPECT_TRUE(fs::exists(kit / "framework/numerics/msm_exact_table.cpp"));
    EXPECT_TRUE(fs::is_regular_file(kit / "kit") &&
                (fs::status(kit / "kit").permissions() & fs::perms::owner_exec) != fs::perms::none);

    // Its docs are the student variants: no instructor block, no pointer at what is missing.
    for (const char* doc : {"README.md", "docs/handout.md"}) {
        const std::string text = test::readFile(kit / doc);
        for (const char* word : {"<!--", "tests/submissions", "tests/oracles", "reference/*", "catalogue.md"})
            EXPECT_EQ(text.find(word), std::string::npos) << doc << " mentions " << word;
        static const std::regex link(R"(\]\(([^)#:]+)(#[^)]*)?\))");
        for (std::sregex_iterator it(text.begin(), text.end(), link), end; it != end; ++it)
            EXPECT_TRUE(fs::exists((kit / doc).parent_path() / (*it)[1].str()))
                << doc << " links to a missing " << (*it)[1].str();
    }

    // performance.md ships without its instructor blocks, so without a pointer at the log.
    EXPECT_EQ(test::readFile(kit / "docs/performance.md").find("performance_log"), std::string::npos);

    // Build the program as `./kit demo` does, and time it.
    const auto t0 = Clock::now();
    auto build = test::buildKitProgram(kit);
    const double buildSeconds = std::chrono::duration<double>(Clock::now() - t0).count();
    ASSERT_EQ(build.exitCode, 0) << build.output;
    std::cout << "student kit: shadowlab built in " << buildSeconds << " s\n";

    // Every command its README and handout show, in their order, ./kit test included.
    std::vector<std::string> commands;
    for (const char* doc : {"README.md", "docs/handout.md"})
        for (const auto& c : test::documentedCommands(test::readFile(kit / doc)))
            if (std::find(commands.begin(), commands.end(), c) == commands.end()) commands.push_back(c);
    ASSERT_GE(commands.size(), 10u);
    std::string skipped;
    const std::string failures = test::runDocumentedCommands(
        kit, commands, false, "env -u SHADOWLAB_ROOT -u SHADOWLAB_BUILD", &skipped);
    EXPECT_EQ(failures, "");
    std::cout << skipped;
    // The demo rendered the student's stages; the self-check graded them against the goldens.
    EXPECT_TRUE(fs::exists(kit / "out/demo/student/classic/final.png"));
    EXPECT_FALSE(fs::exists(kit / "out/demo/reference"));
    EXPECT_TRUE(fs::exists(kit / "out/grade/results.json"));
}

}  // namespace sl
