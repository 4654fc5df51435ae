// batch_store: a batch's rows on disk, each under the digest of what it graded.
#include "batch_store.h"

#include "golden.h"
#include "image_io.h"
#include "jobs.h"
#include "out_guard.h"
#include "paths.h"
#include "scene_list.h"

#include <algorithm>
#include <fstream>
#include <sstream>

namespace sl::grader {
namespace {

constexpr std::uintmax_t kHashedBytes = std::uintmax_t(64) << 20;

// One line per entry: kind, relative path, size and content digest.
void digestLines(const fs::path& dir, std::ostringstream& lines) {
    std::vector<fs::path> entries;
    std::error_code ec;
    for (fs::recursive_directory_iterator it(dir, fs::directory_options::skip_permission_denied, ec), end;
         !ec && it != end; it.increment(ec))
        entries.push_back(it->path());
    std::sort(entries.begin(), entries.end());
    for (const auto& p : entries) {
        const std::string rel = fs::relative(p, dir, ec).generic_string();
        const auto st = fs::symlink_status(p, ec);
        if (fs::is_symlink(st)) {
            lines << "link " << rel << " -> " << fs::read_symlink(p, ec).string() << "\n";
        } else if (fs::is_regular_file(st)) {
            const auto size = fs::file_size(p, ec);
            std::string content;
            if (size > kHashedBytes) {
                const auto when = fs::last_write_time(p, ec).time_since_epoch().count();
                content = "mtime " + std::to_string(when);
            } else {
                try {
                    content = sha256File(p);
                } catch (const std::exception&) {
                    content = "unreadable";
                }
            }
            lines << "file " << rel << " " << size << " " << content << "\n";
        } else if (fs::is_directory(st)) {
            lines << "dir " << rel << "\n";
        }
    }
}

std::string fileDigest(const fs::path& p) {
    std::error_code ec;
    if (!fs::is_regular_file(p, ec)) return "absent";
    try {
        return sha256File(p);
    } catch (const std::exception&) {
        return "unreadable";
    }
}

}  // namespace

std::string submissionDigest(const fs::path& dir) {
    std::ostringstream lines;
    digestLines(dir, lines);
    return sha256Hex(lines.str());
}

std::string setupDigest(const GradeOptions& o) {
    std::ostringstream s;
    s << "shadowlab batch setup 1\n";
    s << "grader " << fileDigest("/proc/self/exe") << "\n";
    s << "shaders " << submissionDigest(repoRoot() / "shaders") << "\n";
    s << "rubric " << fileDigest(o.rubric.empty() ? repoRoot() / "grader" / "rubric.json" : o.rubric) << "\n";
    const std::string mode = resolveReferenceMode(o.reference);
    s << "reference " << mode << "\n";
    const fs::path goldens = o.goldens.empty() ? repoRoot() / "scenes" / "goldens" : o.goldens;
    try {
        for (const auto& scene : gradedScenes(o.scenes)) {
            s << "scene " << scene.name << " " << fileDigest(scene.path) << "\n";
            if (mode == "golden")
                s << "goldens " << fileDigest(goldenFolder(scene, goldens) / "manifest.json") << "\n";
        }
    } catch (const std::exception& e) {
        s << "scenes unreadable: " << e.what() << "\n";  // every grade fails alike; its row says why
    }
    if (mode == "live") s << "solution " << submissionDigest(repoRoot() / "reference") << "\n";
    s << "limits " << o.timeoutSeconds << " " << o.memoryMb << " backend " << o.backend << " report "
      << o.report << "\n";
    return sha256Hex(s.str());
}

std::string rowDigest(const std::string& submission, const std::string& setup) {
    return sha256Hex("submission " + submission + "\nsetup " + setup + "\n");
}

fs::path rowPath(const fs::path& out, const std::string& name) { return out / name / "row.json"; }

std::optional<BatchRow> storedRow(const fs::path& out, const std::string& name, const std::string& digest) {
    std::ifstream in(rowPath(out, name));
    if (!in) return std::nullopt;
    const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
    try {
        BatchRow row = BatchRow::fromJson(j);
        std::error_code ec;
        if (row.digest != digest || !fs::is_regular_file(out / name / "results.json", ec)) return std::nullopt;
        return row;
    } catch (const std::invalid_argument&) {
        return std::nullopt;  // a row of an older grader, or cut short: graded again
    }
}

void storeRow(const fs::path& out, const std::string& name, const BatchRow& row) {
    writeFileSafely(rowPath(out, name), row.toJson().dump(2) + "\n");
}

}  // namespace sl::grader
