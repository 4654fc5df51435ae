// package.h: the student kit and the Gradescope autograder (`shadowlab package`).
#pragma once

#include <filesystem>
#include <string>

namespace sl::grader {

// kind "student": a .tar.gz of the kit without reference/, the solution-bearing test
// submissions, hidden scenes or build outputs. kind "gradescope": a .zip with setup.sh and
// run_autograder at its root and the whole kit (reference/ and hidden scenes included) in
// source/. Returns a one-line summary; throws std::runtime_error.
std::string makePackage(const std::string& kind, const std::filesystem::path& out);

}  // namespace sl::grader
