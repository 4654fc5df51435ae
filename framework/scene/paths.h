// paths: where the kit's folders are, and what `--solution` names.
#pragma once

#include <filesystem>
#include <string>

namespace sl {

namespace fs = std::filesystem;

// The kit's root folder (reference/, student/, scenes/, shaders/, grader/rubric.json), in this
// order: $SHADOWLAB_ROOT if set; else the kit that holds the running program (walking up from
// its folder: build/shadowlab lives in the kit it was built for, even in a copied kit); else the
// kit that holds the current folder; else the source tree the program was built from.
fs::path repoRoot();

// How repoRoot() was found, in words ("$SHADOWLAB_ROOT", "the program's location", ...).
std::string repoRootOrigin();

// The source tree this program was built from (fixed at configure time).
fs::path buildSourceDir();

// Empty, or a one-line warning when the kit in use is not the tree this program was built
// from (a copied kit with a stale build, or $SHADOWLAB_ROOT naming another kit).
std::string repoRootWarning();

// Whether `dir` looks like a Shadowlab kit: the `kit` script, scenes/ and shaders/.
bool isKitRoot(const fs::path& dir);

// "reference" and "student" name the kit's folders; anything else is a folder path. Throws
// std::runtime_error if the folder does not exist.
fs::path resolveSolution(const std::string& solution);

// The solution a command runs when none is named: "reference" where the kit has it (the
// instructor kit), else "student" (the student kit).
std::string defaultSolution();

}  // namespace sl
