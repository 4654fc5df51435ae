// package: copies the chosen parts of the repository into a scratch folder and archives it
// with the system's tar or zip (an instructor's tool: it runs nothing from submissions).
// What the student kit leaves out is the point of this file: reference/ (the solution),
// tests/submissions/ (mutants and correct alternatives: solutions too), scenes/hidden/.
#include "package.h"

#include "paths.h"

#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <vector>
#include <fstream>
#include <stdexcept>

namespace sl::grader {
namespace {

namespace fs = std::filesystem;

const char* kSetup = R"SH(#!/usr/bin/env bash
# Gradescope setup: install the Debian packages and build (runs once, in the image).
set -euo pipefail
cd /autograder/source
./kit deps
cmake --preset default
cmake --build --preset default -j"$(nproc)" --target shadowlab
)SH";

const char* kRun = R"SH(#!/usr/bin/env bash
# Gradescope run: grade /autograder/submission into /autograder/results/results.json.
# Public scenes plus every scenes/hidden/*.json (after_due_date visibility).
cd /autograder/source
mkdir -p /autograder/results
scenes=public
for f in scenes/hidden/*.json; do [ -e "$f" ] && scenes="$scenes,$PWD/$f"; done
build/shadowlab grade --submission /autograder/submission --out /autograder/results \
  --reference live --scenes "$scenes" --no-report
exit 0  # a low score is not a failed autograder: results.json says everything
)SH";

// The kit's own top-level entries (an allow-list: build/, out/, .git and the like stay out).
bool excluded(const fs::path& rel, bool student) {
    static const std::vector<std::string> kit = {"CMakeLists.txt", "CMakePresets.json", "README.md",
                                                 "kit", "docs", "framework", "grader", "scenes",
                                                 "shaders", "student", "tests", "reference"};
    const std::string first = rel.begin()->string();
    if (std::find(kit.begin(), kit.end(), first) == kit.end()) return true;
    if (!student) return false;
    const std::string s = rel.generic_string();
    return first == "reference" || s.rfind("tests/submissions", 0) == 0 ||
           s.rfind("scenes/hidden", 0) == 0;
}

void copyTree(const fs::path& root, const fs::path& dest, bool student) {
    fs::create_directories(dest);
    for (auto it = fs::recursive_directory_iterator(root); it != fs::recursive_directory_iterator(); ++it) {
        const fs::path rel = fs::relative(it->path(), root);
        if (excluded(rel, student)) {
            if (it->is_directory()) it.disable_recursion_pending();
            continue;
        }
        if (it->is_symlink()) continue;
        if (it->is_directory()) fs::create_directories(dest / rel);
        else if (it->is_regular_file()) fs::copy_file(it->path(), dest / rel);
    }
}

void run(const std::string& command) {
    if (std::system(command.c_str()) != 0) throw std::runtime_error("failed: " + command);
}

std::string quote(const fs::path& p) {
    std::string q(1, '\'');
    q += p.string();
    q.push_back('\'');
    return q;
}

}  // namespace

std::string makePackage(const std::string& kind, const fs::path& outArg) {
    const fs::path root = repoRoot();
    const fs::path out = fs::absolute(outArg);
    const fs::path scratch = fs::temp_directory_path() / ("shadowlab-package-" + std::to_string(::getpid()));
    std::error_code ec;
    fs::remove_all(scratch, ec);
    fs::create_directories(out.parent_path());
    fs::remove(out, ec);
    if (kind == "student") {
        copyTree(root, scratch / "shadowlab", true);
        run("tar -czf " + quote(out) + " -C " + quote(scratch) + " shadowlab");
    } else if (kind == "gradescope") {
        copyTree(root, scratch / "source", false);
        std::ofstream(scratch / "setup.sh") << kSetup;
        std::ofstream(scratch / "run_autograder") << kRun;
        fs::permissions(scratch / "setup.sh", fs::perms::owner_all | fs::perms::group_read | fs::perms::others_read);
        fs::permissions(scratch / "run_autograder", fs::perms::owner_all | fs::perms::group_read | fs::perms::others_read);
        run("cd " + quote(scratch) + " && zip -qr " + quote(out) + " setup.sh run_autograder source");
    } else {
        throw std::runtime_error("package kind must be student or gradescope");
    }
    fs::remove_all(scratch, ec);
    return "wrote " + out.string() + " (" + std::to_string(fs::file_size(out) / 1024) + " KiB)";
}

}  // namespace sl::grader
