// out_guard.h: where the grader may write. OUT is the grader's own folder: it removes and
// rewrites things there (report/, .work-<pid>/, results.json), so an OUT that is, contains or
// lies inside the submission, the scenes, the reference or the goldens would destroy them
// (a student's report/ folder; later grades, which read every scenes/*.json). Files are
// written so that a symbolic link planted in OUT is never followed.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace sl::grader {

namespace fs = std::filesystem;

// "" if `out` may be used as the grader's output folder; else why not, naming the option.
// `guarded`: the submission (or batch folder), scenes/, reference/, the goldens.
std::string outFolderProblem(const fs::path& out, const std::vector<fs::path>& guarded);

// The folders no OUT may touch for this grade (the kit's scenes/, reference/, shaders/,
// student/, the goldens, and `submission`).
std::vector<fs::path> guardedFolders(const fs::path& submission, const fs::path& goldens);

// Writes `content` to `path` through a fresh file: an existing `path` or `path.tmp` (a file
// or a symbolic link) is unlinked, never followed; the new file is created with
// O_EXCL | O_NOFOLLOW and renamed into place. Throws std::runtime_error on failure.
void writeFileSafely(const fs::path& path, const std::string& content);

}  // namespace sl::grader
