// The user pages are the manual, docs/performance_log.md the lab notebook. A page a student or
// instructor reads (README.md, docs/*.md but the log) says what is true now, with the figure
// and the command that measures it: no date, no clock time, no "session" or "helper's build"
// of the people who measured it, no commit hash. Dated runs, before / after histories and the
// designs tried go to the log. And a source comment states its requirement in words instead of
// pointing at an issue tracker's number, which means nothing to the next reader.
#include "gl_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <regex>
#include <set>
#include <string>
#include <vector>

namespace sl {
namespace {

std::vector<fs::path> notebookUserPages() {
    std::vector<fs::path> pages{test::root() / "README.md"};
    for (const auto& entry : fs::directory_iterator(test::root() / "docs"))
        if (entry.path().extension() == ".md" && entry.path().filename() != "performance_log.md")
            pages.push_back(entry.path());
    std::sort(pages.begin(), pages.end());
    return pages;
}

// "file:line: what: the line" for every line of a user page that reads like the lab notebook.
std::vector<std::string> notebookWordsInUserPages() {
    const std::regex date(R"(\b20\d\d-\d\d-\d\d\b)");
    const std::regex clock(R"(\b\d\d:\d\d UTC\b)");
    const std::regex session(R"(\bsessions?\b)", std::regex::icase);
    // "helper" as code (helper lanes, helper functions, a stage's helper files) is fine; the
    // people who measured ("other helpers' builds", "a helper's run") are not.
    const std::regex helper(
        R"(\b(other|another)\s+helpers?\b|\bhelpers?('s|s')?\s+(builds?|tests?|runs?|branch(es)?|work|machines?)\b)",
        std::regex::icase);
    // A commit hash: 7 to 40 lower-case hex digits with at least one digit and one letter.
    const std::regex hash(R"(\b(?=[0-9a-f]*[0-9])(?=[0-9a-f]*[a-f])[0-9a-f]{7,40}\b)");
    std::vector<std::string> found;
    for (const fs::path& page : notebookUserPages()) {
        std::ifstream in(page);
        std::string line;
        bool fenced = false;
        for (int n = 1; std::getline(in, line); ++n) {
            const std::string at = fs::relative(page, test::root()).string() + ":" +
                                   std::to_string(n) + ": ";
            const auto first = line.find_first_not_of(" \t");
            if (first != std::string::npos && line.compare(first, 3, "```") == 0) {
                fenced = !fenced;
                continue;
            }
            if (std::regex_search(line, date)) found.push_back(at + "a date: " + line);
            if (std::regex_search(line, clock)) found.push_back(at + "a clock time: " + line);
            if (std::regex_search(line, session)) found.push_back(at + "\"session\": " + line);
            if (std::regex_search(line, helper)) found.push_back(at + "\"helper\": " + line);
            // In prose (inline code included); a fenced block may show a checksum.
            if (!fenced && std::regex_search(line, hash))
                found.push_back(at + "a commit hash: " + line);
        }
    }
    return found;
}

// Whether a comment's text names an issue by number: the word, an optional "s", a space, an
// optional "#", a digit; in any case.
bool notebookCitesIssue(const std::string& comment) {
    std::string lower(comment);
    std::transform(lower.begin(), lower.end(), lower.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    for (size_t at = lower.find("issue"); at != std::string::npos; at = lower.find("issue", at + 1)) {
        if (at > 0 && std::isalpha(static_cast<unsigned char>(lower[at - 1]))) continue;
        size_t i = at + 5;
        if (i < lower.size() && lower[i] == 's') ++i;
        if (i >= lower.size() || lower[i] != ' ') continue;
        ++i;
        if (i < lower.size() && lower[i] == '#') ++i;
        if (i < lower.size() && std::isdigit(static_cast<unsigned char>(lower[i]))) return true;
    }
    return false;
}

// "file:line: the line" for every source comment that cites an issue by number.
std::vector<std::string> notebookIssueComments() {
    const std::set<std::string> cLike{".cpp", ".h", ".glsl", ".comp", ".frag", ".vert"};
    std::vector<fs::path> files{test::root() / "CMakeLists.txt"};
    for (const char* dir : {"cli", "framework", "grader", "shaders", "reference", "student",
                            "tests", "tools", "kit"}) {
        const fs::path top = test::root() / dir;
        if (!fs::is_directory(top)) continue;
        for (const auto& entry : fs::recursive_directory_iterator(top)) {
            const fs::path& p = entry.path();
            if (entry.is_regular_file() &&
                (cLike.count(p.extension().string()) || p.extension() == ".cmake" ||
                 p.filename() == "CMakeLists.txt"))
                files.push_back(p);
        }
    }
    std::vector<std::string> found;
    for (const fs::path& file : files) {
        const bool cmake = !cLike.count(file.extension().string());
        std::ifstream in(file);
        std::string line;
        for (int n = 1; std::getline(in, line); ++n) {
            const size_t comment = line.find(cmake ? "#" : "//");
            if (comment != std::string::npos && notebookCitesIssue(line.substr(comment)))
                found.push_back(fs::relative(file, test::root()).string() + ":" +
                                std::to_string(n) + ": " + line);
        }
    }
    return found;
}

std::string notebookJoin(const std::vector<std::string>& lines) {
    std::string all;
    for (const std::string& l : lines) all += l + "\n";
    return all;
}

TEST(DocsNotebook, UserPagesCarryNoDateSessionOrCommitHash) {
    EXPECT_GE(notebookUserPages().size(), 10u) << "README.md and docs/*.md not found";
    const std::vector<std::string> found = notebookWordsInUserPages();
    EXPECT_TRUE(found.empty())
        << "lab-notebook text in a user page: move the dated run or the history to "
           "docs/performance_log.md and keep the current figure with its command here:\n"
        << notebookJoin(found);
}

TEST(DocsNotebook, TheCheckSeesWhatItLooksFor) {
    const std::string slash = "/";  // so that this file's own lines hold no such comment
    EXPECT_TRUE(notebookCitesIssue(slash + "/ the goals of issue 10"));
    EXPECT_TRUE(notebookCitesIssue(slash + "/ Hostile input, Issue 7 §4: scene files"));
    EXPECT_TRUE(notebookCitesIssue("# see issues #12"));
    EXPECT_FALSE(notebookCitesIssue("// a known grader issue on SAT scenes"));
    EXPECT_FALSE(notebookCitesIssue("// tissue 4"));
    EXPECT_FALSE(notebookCitesIssue("// docs/numerics.md §5"));
}

TEST(DocsNotebook, SourceCommentsGiveTheRequirementNotAnIssueNumber) {
    const std::vector<std::string> found = notebookIssueComments();
    EXPECT_TRUE(found.empty()) << "a comment cites an issue by number; say the requirement in "
                                  "words:\n"
                               << notebookJoin(found);
}

}  // namespace
}  // namespace sl
