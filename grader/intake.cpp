// intake: the only door from a submission into the grader. Only the five expected names are
// looked at; each is opened with O_NOFOLLOW and checked on the open descriptor (no race
// between the check and the read), then copied into a folder the grader owns, so that the
// renders never read from the submission itself. Nothing in the submission is executed: the
// files are GLSL handed to the driver.
#include "intake.h"

#include "shader_source.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fstream>
#include <regex>
#include <set>
#include <sstream>

namespace sl::grader {
namespace {

// Reads `path` if it is a plain file of at most the size limit; else returns a reason.
std::string readChecked(const fs::path& path, std::string& content) {
    struct stat ls {};
    if (::lstat(path.c_str(), &ls) != 0) return "not submitted";
    if (S_ISLNK(ls.st_mode)) return "refused: it is a symbolic link (submit the file itself)";
    if (!S_ISREG(ls.st_mode)) return "refused: not a regular file";
    int fd = ::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
    if (fd < 0) return "refused: cannot be opened";
    struct stat st {};
    if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        ::close(fd);
        return "refused: not a regular file";
    }
    if (std::uintmax_t(st.st_size) > kMaxSubmissionFileBytes) {
        ::close(fd);
        return "refused: " + std::to_string(st.st_size) + " bytes, over the limit of 256 KiB";
    }
    content.clear();
    char buf[16384];
    ssize_t n;
    while ((n = ::read(fd, buf, sizeof buf)) > 0) {
        content.append(buf, size_t(n));
        if (content.size() > kMaxSubmissionFileBytes) break;  // grew while we read
    }
    ::close(fd);
    if (content.size() > kMaxSubmissionFileBytes) return "refused: over the limit of 256 KiB";
    return "";
}

// An #include may name another stage file or a framework file by its bare name; a path
// (slash, backslash, "..") could read files outside the submission, so it is refused.
std::string checkIncludes(const std::string& content) {
    static const std::regex include(R"(^\s*#\s*include\s*[<"]([^>"]*)[>"])");
    std::istringstream in(content);
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        std::smatch m;
        if (!std::regex_search(line, m, include)) continue;
        const std::string name = m[1];
        if (name.find('/') != std::string::npos || name.find('\\') != std::string::npos ||
            name.find("..") != std::string::npos || name.empty())
            return "refused: line " + std::to_string(number) + ": #include \"" + name +
                   "\" is a path; include files by their bare name";
    }
    if (content.find('\0') != std::string::npos) return "refused: binary file (NUL bytes)";
    return "";
}

}  // namespace

IntakeResult takeSubmission(const fs::path& submission, const fs::path& staging) {
    IntakeResult r;
    r.staged = staging;
    std::error_code ec;
    fs::remove_all(staging, ec);
    fs::create_directories(staging);
    const auto& names = stageFileNames();
    struct stat ds {};
    const bool dirOk = ::lstat(submission.c_str(), &ds) == 0 && S_ISDIR(ds.st_mode);
    for (const std::string& name : names) {
        if (!dirOk) {
            r.refused[name] = "not submitted (no submission folder " + submission.string() + ")";
            continue;
        }
        std::string content;
        std::string reason = readChecked(submission / name, content);
        if (reason.empty()) reason = checkIncludes(content);
        if (!reason.empty()) {
            r.refused[name] = reason;
            continue;
        }
        std::ofstream(staging / name, std::ios::binary) << content;
        r.accepted.push_back(name);
    }
    if (dirOk) {
        std::set<std::string> expected(names.begin(), names.end());
        for (const auto& entry : fs::directory_iterator(submission, ec))
            if (!expected.count(entry.path().filename().string()))
                r.ignored.push_back(entry.path().filename().string());
    }
    return r;
}

}  // namespace sl::grader
