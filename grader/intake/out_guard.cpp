// out_guard: the checks on OUT and the link-proof file writes (out_guard.h).
#include "out_guard.h"

#include "paths.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace sl::grader {
namespace {

fs::path resolved(const fs::path& p) {
    std::error_code ec;
    fs::path c = fs::weakly_canonical(fs::absolute(p, ec), ec);
    return ec ? fs::absolute(p).lexically_normal() : c;
}

// `inner` is `outer` or lies inside it.
bool within(const fs::path& inner, const fs::path& outer) {
    const fs::path rel = inner.lexically_relative(outer);
    return !rel.empty() && *rel.begin() != "..";
}

}  // namespace

std::vector<fs::path> guardedFolders(const fs::path& submission, const fs::path& goldens) {
    const fs::path root = repoRoot();
    std::vector<fs::path> g = {root / "scenes", root / "reference", root / "shaders",
                               root / "student", goldens.empty() ? root / "scenes" / "goldens" : goldens};
    if (!submission.empty()) g.push_back(submission);
    return g;
}

std::string outFolderProblem(const fs::path& out, const std::vector<fs::path>& guarded) {
    if (out.empty()) return "--out: no output folder given";
    struct stat st {};
    if (::stat(out.c_str(), &st) == 0 && !S_ISDIR(st.st_mode))
        return "--out " + out.string() + ": exists and is not a folder (give a folder for "
               "results.json and report/)";
    const fs::path o = resolved(out);
    for (const auto& g : guarded) {
        const fs::path c = resolved(g);
        if (within(o, c) || within(c, o))
            return "--out " + out.string() + ": refused: it " +
                   (o == c ? "is" : within(o, c) ? "lies inside" : "contains") + " " + g.string() +
                   " (the grader removes and rewrites files in its output folder; give a "
                   "folder of its own)";
    }
    return "";
}

void writeFileSafely(const fs::path& path, const std::string& content) {
    const fs::path tmp = path.string() + ".tmp";
    ::unlink(tmp.c_str());  // a file or a link someone left there: gone, not followed
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
    if (fd < 0)
        throw std::runtime_error("cannot create " + tmp.filename().string() + ": " + std::strerror(errno));
    size_t written = 0;
    while (written < content.size()) {
        const ssize_t n = ::write(fd, content.data() + written, content.size() - written);
        if (n <= 0) {
            ::close(fd);
            ::unlink(tmp.c_str());
            throw std::runtime_error("cannot write " + path.filename().string());
        }
        written += size_t(n);
    }
    ::close(fd);
    // rename() replaces a link at `path` itself, never its target.
    if (::rename(tmp.c_str(), path.c_str()) != 0) {
        ::unlink(tmp.c_str());
        throw std::runtime_error("cannot write " + path.filename().string() + ": " + std::strerror(errno));
    }
}

}  // namespace sl::grader
