// Every command line README.md and docs/handout.md show runs, as written (kit_test_support.h
// says the three exceptions), from a folder laid out like the kit's root: a new line in either
// file is tested without touching this file. Also: --backend before and after the subcommand.
#include "kit_test_support.h"

#include <cctype>
#include <set>

namespace sl {
namespace {

// A scratch folder that looks like the kit's root: its entries are links to the real ones,
// build/ is this test's build folder; outputs (out/, cases.csv) land in the scratch folder.
// Two entries are copies: `kit` (it takes its root from its own real path: a link would send
// ./kit's outputs into the real kit's out/) and `student/` (the grader takes no submission
// folder that is a link: `grade --submission student` would grade nothing).
fs::path kitLookalike(const std::string& name) {
    fs::path dir = test::tempDir(name);
    for (const auto& e : fs::directory_iterator(test::root())) {
        const std::string n = e.path().filename().string();
        if (n == "build" || n.rfind("build-", 0) == 0 || n == "out" || n.rfind(".", 0) == 0) continue;
        if (n == "kit" || n == "student")
            fs::copy(e.path(), dir / n, fs::copy_options::recursive);
        else
            fs::create_symlink(e.path(), dir / n);
    }
    fs::create_symlink(test::buildDir(), dir / "build");
    return dir;
}

}  // namespace

TEST(ReadmeCommands, ExtractionFindsBlockAndInlineCommands) {
    const std::string md = "Run\n```sh\n./kit demo   # builds\n  # comment only\n"
                           "build/shadowlab info\nxvfb-run -a build/shadowlab view --scene s.json  # no display\n"
                           "```\nthen `build/shadowlab grade --submission\n"
                           "student --out g` and `probe moments`.\n";
    const auto c = test::documentedCommands(md);
    ASSERT_EQ(c.size(), 4u) << testing::PrintToString(c);
    EXPECT_EQ(c[0], "./kit demo");
    EXPECT_EQ(c[1], "build/shadowlab info");
    EXPECT_EQ(c[2], "xvfb-run -a build/shadowlab view --scene s.json");
    EXPECT_EQ(c[3], "build/shadowlab grade --submission student --out g");
}

TEST(ReadmeCommands, EveryReadmeAndHandoutCommandRunsAsWritten) {
    const fs::path dir = kitLookalike("readme_commands");
    std::vector<std::string> commands;
    for (const char* doc : {"README.md", "docs/handout.md"})
        for (const auto& c : test::documentedCommands(test::readFile(test::root() / doc)))
            if (std::find(commands.begin(), commands.end(), c) == commands.end()) commands.push_back(c);
    ASSERT_GE(commands.size(), 10u) << testing::PrintToString(commands);
    std::string skipped;
    const std::string env = "SHADOWLAB_BUILD='" + test::buildDir().string() + "'";
    const std::string failures = test::runDocumentedCommands(dir, commands, true, env, &skipped);
    EXPECT_EQ(failures, "");
    std::cout << "ran " << commands.size() << " documented commands\n" << skipped;
    EXPECT_TRUE(fs::exists(dir / "out/classic/final.png"));
    if (skipped.find("no xvfb-run") == std::string::npos)  // README: view --screenshot
        EXPECT_TRUE(fs::exists(dir / "out/view.png"));
    EXPECT_GT(fs::file_size(dir / "cases.csv"), 1000u);
    // ./kit wrote into the scratch folder; the grades graded the stubs (the stage files taken).
    EXPECT_TRUE(fs::exists(dir / "out/demo/student/classic/final.png"));
    EXPECT_TRUE(fs::exists(dir / "out/report/index.html"));
    const std::string results = test::readFile(dir / "out/grade/results.json");
    EXPECT_NE(results.find("not implemented"), std::string::npos) << results.substr(0, 2000);
    EXPECT_EQ(results.find("not submitted"), std::string::npos) << results.substr(0, 2000);
}

// A link to a section ("handout.md#grading-yourself-kit-check", "#the-report") finds a heading
// of that page whose GitHub anchor it is (lower case, punctuation dropped, spaces as hyphens).
TEST(ReadmeCommands, LinksToASectionFindItsHeading) {
    auto anchors = [](const fs::path& page) {
        std::set<std::string> out;
        std::istringstream in(test::readFile(page));
        for (std::string line; std::getline(in, line);) {
            if (line.rfind("#", 0) != 0) continue;
            std::string title = line.substr(line.find_first_not_of('#')), slug;
            for (unsigned char c : title)
                if (std::isalnum(c) || c == '-' || c == '_' || c >= 0x80) slug += char(std::tolower(c));
                else if (c == ' ') slug += '-';
            out.insert(slug.substr(slug.find_first_not_of('-')));
        }
        return out;
    };
    int links = 0;
    for (const char* doc : {"README.md", "docs/handout.md", "docs/grading.md", "docs/numerics.md",
                            "docs/stage_contract.md"}) {
        const fs::path page = test::root() / doc;
        const std::string text = test::readFile(page);
        static const std::regex link(R"(\]\(([^)#:]*)#([^)]+)\))");
        for (std::sregex_iterator it(text.begin(), text.end(), link), end; it != end; ++it, ++links) {
            const fs::path target = (*it)[1].str().empty() ? page : page.parent_path() / (*it)[1].str();
            EXPECT_TRUE(anchors(target).count((*it)[2].str())) << doc << ": " << (*it)[0] << " finds no heading";
        }
    }
    EXPECT_GE(links, 3);
}

// README: `build/shadowlab render ... --backend egl` (as the README shows it): the option after the
// subcommand, on every subcommand that renders, and before it as before.
TEST(ReadmeCommands, BackendIsAcceptedBeforeAndAfterEverySubcommandThatRenders) {
    const std::string bin = test::shadowlabBinary();
    for (const char* sub : {"render", "view", "grade", "golden", "bench", "probe", "info"}) {
        auto r = test::runCommand(bin + " " + sub + " --help");
        EXPECT_NE(r.output.find("--backend"), std::string::npos) << sub << ":\n" << r.output;
    }
    const fs::path out = test::tempDir("backend_positions");
    for (const std::string& line :
         {bin + " render --scene " + test::scenePath("classic").string() + " --out " +
              (out / "after").string() + " --backend egl",
          bin + " --backend egl render --scene " + test::scenePath("classic").string() +
              " --out " + (out / "before").string()}) {
        auto r = test::runCommand(line);
        ASSERT_EQ(r.exitCode, 0) << line << "\n" << r.output;
        EXPECT_NE(r.output.find("egl"), std::string::npos) << r.output;
    }
    auto info = test::runCommand(bin + " info --backend egl");
    EXPECT_NE(info.output.find("backend:  egl"), std::string::npos) << info.output;
    auto bad = test::runCommand(bin + " bench --backend vulkan");
    EXPECT_NE(bad.exitCode, 0);
    EXPECT_NE(bad.output.find("vulkan"), std::string::npos) << bad.output;
}

}  // namespace sl
