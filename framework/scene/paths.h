// paths: where the kit's folders are, and what `--solution` names.
#pragma once

#include <filesystem>
#include <string>

namespace sl {

namespace fs = std::filesystem;

// The repository root: $SHADOWLAB_ROOT if set, else the source tree the binary was built from.
fs::path repoRoot();

// "reference" and "student" name the kit's folders; anything else is a folder path. Throws
// std::runtime_error if the folder does not exist.
fs::path resolveSolution(const std::string& solution);

}  // namespace sl
