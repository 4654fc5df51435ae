// intake: the only door from a submission into the grader. Only the five stage names and
// helper `.glsl` files are looked at; each is opened with O_NOFOLLOW and checked on the open
// descriptor (no race between the check and the read), then copied into a folder the grader
// owns, so that the renders never read from the submission itself. Nothing in the submission
// is executed: the files are GLSL handed to the driver. The text is scanned by hand
// (glsl_scan.h), never with std::regex: a 40 000-character line overflowed its stack.
#include "intake.h"

#include "glsl_scan.h"
#include "shader_source.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <set>

namespace sl::grader {
namespace {

// Reads `path` if it is a plain file of at most `limit` bytes; else returns a reason.
std::string readChecked(const fs::path& path, std::string& content,
                        std::uintmax_t limit = kMaxSubmissionFileBytes) {
    struct stat ls {};
    if (::lstat(path.c_str(), &ls) != 0) return "not submitted";
    if (S_ISLNK(ls.st_mode)) return "refused: it is a symbolic link (submit the file itself)";
    if (!S_ISREG(ls.st_mode)) return "refused: not a regular file";
    int fd = ::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC | O_NONBLOCK);
    if (fd < 0) return "refused: cannot be opened";
    struct stat st {};
    if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        ::close(fd);
        return "refused: not a regular file";
    }
    const std::string over = "refused: over the limit of " + std::to_string(limit / 1024) + " KiB";
    if (std::uintmax_t(st.st_size) > limit) {
        ::close(fd);
        return "refused: " + std::to_string(st.st_size) + " bytes, over the limit of " +
               std::to_string(limit / 1024) + " KiB";
    }
    content.clear();
    char buf[16384];
    ssize_t n;
    while ((n = ::read(fd, buf, sizeof buf)) > 0) {
        content.append(buf, size_t(n));
        if (content.size() > limit) break;  // grew while we read
    }
    ::close(fd);
    if (content.size() > limit) return over;
    return "";
}

// A helper's name: letters, digits, '_', '-', '.', not hidden, ending in .glsl.
bool helperName(const std::string& name) {
    if (name.size() < 6 || name.size() > 64 || name[0] == '.' || !name.ends_with(".glsl"))
        return false;
    return std::all_of(name.begin(), name.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.';
    });
}

bool isStage(const std::string& name) {
    const auto& n = stageFileNames();
    return std::find(n.begin(), n.end(), name) != n.end();
}

// The folder the files are in: `submission`, or its one subfolder when only that holds them.
fs::path filesFolder(const fs::path& submission, std::string& nested) {
    std::error_code ec;
    std::vector<fs::path> dirs;
    for (const auto& entry : fs::directory_iterator(submission, ec)) {
        const std::string name = entry.path().filename().string();
        if (isStage(name)) return submission;
        if (name[0] == '.' || name == "__MACOSX") continue;  // archive tools' leftovers
        struct stat ls {};
        if (::lstat(entry.path().c_str(), &ls) == 0 && S_ISDIR(ls.st_mode)) dirs.push_back(entry.path());
    }
    if (dirs.size() != 1) return submission;
    for (const auto& name : stageFileNames()) {
        struct stat ls {};
        if (::lstat((dirs[0] / name).c_str(), &ls) == 0) {
            nested = dirs[0].filename().string();
            return dirs[0];
        }
    }
    return submission;
}

}  // namespace

// An #include may name another stage file, a helper of the submission or a framework file by
// its bare name; a path (slash, backslash, "..") could read files outside the submission, so
// it is refused. #line would let a file claim to be another; #extension cannot follow code.
std::string checkSource(const std::string& content) {
    if (content.find('\0') != std::string::npos) return "refused: binary file (NUL bytes)";
    glsl::LineScanner scanner;
    int number = 0;
    for (std::string_view line : glsl::splitLines(content)) {
        ++number;
        const auto d = scanner.scan(line);
        if (!d) continue;
        const std::string at = "refused: line " + std::to_string(number) + ": ";
        if (d->name == "line")
            return at + "#line is not allowed (errors must point at your own lines)";
        if (d->name == "extension")
            return at + "#extension is not allowed (the framework compiles GLSL 4.50 core)";
        if (d->name != "include") continue;
        const auto name = glsl::includeName(d->argument);
        std::string shown = name ? *name : d->argument;
        if (shown.size() > 80) shown = shown.substr(0, 77) + "...";
        if (!name || name->empty())
            return at + "#include " + shown + ": write #include \"file.glsl\"";
        if (name->find('/') != std::string::npos || name->find('\\') != std::string::npos ||
            name->find("..") != std::string::npos)
            return at + "#include \"" + shown + "\" is a path; include files by their bare name";
    }
    return "";
}

IntakeResult takeSubmission(const fs::path& submission, const fs::path& staging) {
    // Test hook (tests/test_hostile_batch_isolation.cpp): the grading process itself crashes.
    if (const char* fault = std::getenv("SHADOWLAB_GRADER_FAULT");
        fault && std::string(fault) == "intake:" + submission.filename().string())
        std::raise(SIGSEGV);
    IntakeResult r;
    r.staged = staging;
    std::error_code ec;
    fs::remove_all(staging, ec);
    fs::create_directories(staging);
    const auto& names = stageFileNames();
    struct stat ds {};
    const bool dirOk = ::lstat(submission.c_str(), &ds) == 0 && S_ISDIR(ds.st_mode);
    const fs::path folder = dirOk ? filesFolder(submission, r.nested) : submission;
    for (const std::string& name : names) {
        if (!dirOk) {
            r.refused[name] = "not submitted (no submission folder)";
            continue;
        }
        std::string content;
        std::string reason = readChecked(folder / name, content);
        if (reason.empty()) reason = checkSource(content);
        if (!reason.empty()) {
            r.refused[name] = reason;
            continue;
        }
        std::ofstream(staging / name, std::ios::binary) << content;
        r.accepted.push_back(name);
    }
    if (!dirOk) return r;
    std::vector<std::string> others;
    for (const auto& entry : fs::directory_iterator(folder, ec)) {
        const std::string name = entry.path().filename().string();
        if (!isStage(name)) others.push_back(name);
    }
    std::sort(others.begin(), others.end());
    std::uintmax_t helperBytes = 0;
    for (const auto& name : others) {
        if (!helperName(name)) {
            r.ignored.push_back(name);
            continue;
        }
        std::string content;
        std::string reason = r.includes.size() >= kMaxIncludeFiles
                                 ? "more than " + std::to_string(kMaxIncludeFiles) + " .glsl helpers"
                                 : readChecked(folder / name, content);
        if (reason.empty()) reason = checkSource(content);
        if (reason.empty() && helperBytes + content.size() > kMaxIncludeBytes)
            reason = "helpers over " + std::to_string(kMaxIncludeBytes / 1024) + " KiB in all";
        if (!reason.empty()) {
            r.ignored.push_back(name + " (" + reason + ")");
            continue;
        }
        helperBytes += content.size();
        std::ofstream(staging / name, std::ios::binary) << content;
        r.includes.push_back(name);
    }
    return r;
}

}  // namespace sl::grader
