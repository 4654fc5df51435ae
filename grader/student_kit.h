// student_kit.h: what the student kit (`shadowlab package --kind student`) leaves out and how
// it rewrites what it keeps, so that nothing in it bears the solution and its docs are true
// there (docs/grading.md, "What the student kit contains").
#pragma once

#include <filesystem>
#include <set>
#include <string>

namespace sl::grader {

// Paths (relative to the kit's root, '/'-separated) that never go into the student kit:
// reference/, tests/oracles/ (double-precision mirrors of every stage), tests/submissions/
// (mutants and correct alternatives), scenes/hidden/ (with their goldens), the exact 4MSM
// (framework/numerics/msm_exact.cpp), docs/catalogue.md (describes the submissions),
// docs/performance_log.md (the measurements of the reference's designs), and the
// tests that need any of these (found by their includes and text, see studentKitDroppedTests).
bool leftOutOfStudentKit(const std::string& rel, const std::set<std::string>& droppedTests);

// The files under root/tests/ that need what the kit leaves out: those naming oracles/,
// msm_exact or the submissions folder, and those including such a file (transitively).
std::set<std::string> studentKitDroppedTests(const std::filesystem::path& root);

// A Markdown file for the student kit: blocks between the lines `<!-- instructor -->` and
// `<!-- /instructor -->` are removed; lines between `<!-- student` and `-->` are kept as text
// (they are a comment in the full kit). Both markers are whole lines.
std::string studentMarkdown(const std::string& markdown);

// Source of framework/numerics/msm_exact_table.cpp, which replaces msm_exact.cpp in the
// student kit: the exact 4MSM value and its float sensitivity for every input of the named
// probe case sets (the hard-case catalogue included) at the reference's moment bias, as a
// table; any other input throws ("not in the student kit").
std::string msmExactTableSource();

}  // namespace sl::grader
