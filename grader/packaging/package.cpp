// package: copies the chosen parts of the repository into a scratch folder and archives it
// with the system's tar or zip (an instructor's tool: it runs nothing from submissions).
// What the student kit holds (grader/student_kit.manifest) and rewrites is student_kit.h; the
// Gradescope zip's two scripts are here (docs/grading.md, "Packaging" and "Gradescope").
#include "package.h"

#include "paths.h"
#include "student_kit.h"

#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <vector>
#include <fstream>
#include <iterator>
#include <stdexcept>

namespace sl::grader {
namespace {

namespace fs = std::filesystem;

const char* kSetup = R"SH(#!/usr/bin/env bash
# Gradescope setup: install the autograder's Debian packages (./kit deps --grader: no Chromium,
# Xvfb or GoogleTest) and build the shadowlab program; runs once, when the image is built.
# Made for Debian 12 package names (docs/grading.md, "Gradescope"). $SHADOWLAB_AUTOGRADER
# replaces /autograder (the kit's own test runs this script in a temporary folder).
set -euo pipefail
AG="${SHADOWLAB_AUTOGRADER:-/autograder}"
cd "$AG/source"
if [ -r /etc/os-release ]; then . /etc/os-release; echo "setup.sh on ${PRETTY_NAME:-?}"; fi
./kit deps --grader
version="$(cmake --version | sed -n '1s/.* //p')"
if ! printf '3.25\n%s\n' "$version" | sort -V -C; then
  echo "setup.sh: CMake $version is too old; the kit needs 3.25 (Debian 12, Ubuntu 24.04)." >&2
  echo "On Gradescope pick a base image that has it (docs/grading.md, Gradescope)." >&2
  exit 1
fi
cmake --preset default -DBUILD_TESTING=OFF >/dev/null
cmake --build --preset default -j"$(nproc)" --target shadowlab
)SH";

const char* kRun = R"SH(#!/usr/bin/env bash
# Gradescope run: grade $AG/submission into $AG/results/results.json (AG: /autograder, or
# $SHADOWLAB_AUTOGRADER). Public scenes plus every scenes/hidden/*.json (after_due_date), against
# the committed goldens: the stored images the student kit's ./kit check grades against.
AG="${SHADOWLAB_AUTOGRADER:-/autograder}"
cd "$AG/source"
mkdir -p "$AG/results"
scenes=public
for f in scenes/hidden/*.json; do [ -e "$f" ] && scenes="$scenes,$PWD/$f"; done
build/shadowlab grade --submission "$AG/submission" --out "$AG/results" \
  --reference golden --scenes "$scenes" --no-report
exit 0  # a low score is not a failed autograder: results.json says everything
)SH";

// The Gradescope zip: the kit's own top-level entries (an allow-list: build/, out/, .git and the
// like stay out), everything below them.
void copyTree(const fs::path& root, const fs::path& dest) {
    static const std::vector<std::string> kit = {"CMakeLists.txt", "CMakePresets.json", "README.md",
                                                 "kit", "docs", "cli", "framework", "grader", "scenes",
                                                 "shaders", "student", "tests", "reference"};
    fs::create_directories(dest);
    for (auto it = fs::recursive_directory_iterator(root); it != fs::recursive_directory_iterator(); ++it) {
        const fs::path rel = fs::relative(it->path(), root);
        if (std::find(kit.begin(), kit.end(), rel.begin()->string()) == kit.end()) {
            if (it->is_directory()) it.disable_recursion_pending();
            continue;
        }
        if (it->is_symlink()) continue;
        if (it->is_directory()) fs::create_directories(dest / rel);
        else if (it->is_regular_file()) fs::copy_file(it->path(), dest / rel);
    }
}

// The student kit: the files grader/student_kit.manifest names (studentKitFiles), each .md as
// its student variant, and the exact 4MSM's table in place of its solver.
void copyStudentKit(const fs::path& root, const fs::path& dest) {
    for (const auto& rel : studentKitFiles(root)) {
        fs::create_directories((dest / rel).parent_path());
        fs::copy_file(root / rel, dest / rel);
        if (fs::path(rel).extension() == ".md") {
            std::ifstream in(root / rel, std::ios::binary);
            const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
            std::ofstream(dest / rel, std::ios::trunc | std::ios::binary) << studentMarkdown(text);
        }
    }
    fs::create_directories(dest / "framework/numerics");
    std::ofstream(dest / "framework/numerics/msm_exact_table.cpp") << msmExactTableSource();
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
        copyStudentKit(root, scratch / "shadowlab");
        run("tar -czf " + quote(out) + " -C " + quote(scratch) + " shadowlab");
    } else if (kind == "gradescope") {
        copyTree(root, scratch / "source");
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
