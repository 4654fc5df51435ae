// paths: repository root and solution folders (see paths.h).
#include "paths.h"

#include <cstdlib>
#include <optional>
#include <stdexcept>
#include <utility>

namespace sl {
namespace {

std::optional<fs::path> kitAbove(fs::path dir) {
    std::error_code ec;
    dir = fs::weakly_canonical(dir, ec);
    if (ec) return std::nullopt;
    for (; !dir.empty(); dir = dir.parent_path()) {
        if (isKitRoot(dir)) return dir;
        if (dir == dir.root_path()) break;
    }
    return std::nullopt;
}

// Found once per process: the program's location and the current folder do not change.
const std::pair<fs::path, std::string>& discovered() {
    static const std::pair<fs::path, std::string> found = [] {
        std::error_code ec;
        const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
        if (!ec)
            if (auto kit = kitAbove(exe.parent_path())) return std::pair{*kit, std::string("the program's location")};
        if (auto kit = kitAbove(fs::current_path(ec))) return std::pair{*kit, std::string("the current folder")};
        return std::pair{buildSourceDir(), std::string("the tree it was built from")};
    }();
    return found;
}

const char* rootFromEnvironment() {
    const char* env = std::getenv("SHADOWLAB_ROOT");
    return env && *env ? env : nullptr;
}

}  // namespace

bool isKitRoot(const fs::path& dir) {
    std::error_code ec;
    return fs::is_regular_file(dir / "kit", ec) && fs::is_directory(dir / "scenes", ec) &&
           fs::is_directory(dir / "shaders", ec);
}

fs::path buildSourceDir() { return fs::path(SHADOWLAB_SOURCE_DIR); }

fs::path repoRoot() {
    if (const char* env = rootFromEnvironment()) return fs::path(env);
    return discovered().first;
}

std::string repoRootOrigin() {
    return rootFromEnvironment() ? "$SHADOWLAB_ROOT" : discovered().second;
}

std::string repoRootWarning() {
    std::error_code ec;
    const fs::path root = fs::weakly_canonical(repoRoot(), ec);
    const fs::path built = fs::weakly_canonical(buildSourceDir(), ec);
    if (root == built) return "";
    return "warning: this shadowlab was built from " + built.string() + " but uses the kit at " +
           root.string() + " (found from " + repoRootOrigin() +
           "); C++ changes in this kit need a build here (set SHADOWLAB_ROOT to choose the kit)";
}

fs::path resolveSolution(const std::string& solution) {
    fs::path dir = (solution == "reference" || solution == "student") ? repoRoot() / solution
                                                                       : fs::path(solution);
    if (!fs::is_directory(dir))
        throw std::runtime_error("solution folder not found: " + dir.string() +
                                 " (expected reference, student or a folder path)");
    return fs::absolute(dir);
}

std::string defaultSolution() {
    return fs::is_directory(repoRoot() / "reference") ? "reference" : "student";
}

}  // namespace sl
