// paths: repository root and solution folders (see paths.h).
#include "paths.h"

#include <cstdlib>
#include <stdexcept>

namespace sl {

fs::path repoRoot() {
    if (const char* env = std::getenv("SHADOWLAB_ROOT"); env && *env) return fs::path(env);
    return fs::path(SHADOWLAB_SOURCE_DIR);
}

fs::path resolveSolution(const std::string& solution) {
    fs::path dir = (solution == "reference" || solution == "student") ? repoRoot() / solution
                                                                       : fs::path(solution);
    if (!fs::is_directory(dir))
        throw std::runtime_error("solution folder not found: " + dir.string() +
                                 " (expected reference, student or a folder path)");
    return fs::absolute(dir);
}

}  // namespace sl
