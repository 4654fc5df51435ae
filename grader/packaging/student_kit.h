// student_kit.h: what the student kit (`shadowlab package --kind student`) holds and how it
// rewrites it, so that nothing in it bears the solution and its docs are true
// there (docs/grading.md, "What the student kit contains").
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace sl::grader {

// The student kit is packed from an allow-list, grader/student_kit.manifest: one path per line
// (relative to the kit's root, '/'-separated), a file or a folder (everything below it); `#`
// starts a comment; blank lines are ignored. A file it does not name is left out.
inline constexpr const char* kStudentKitManifest = "grader/student_kit.manifest";

// The manifest's entries, in its order, without comments, blanks and trailing '/'. Throws when
// the file is missing or an entry is absolute or climbs out of the kit ("..").
std::vector<std::string> studentKitManifest(const std::filesystem::path& root);

// The files (relative, '/'-separated, sorted) the manifest puts in the student kit: each named
// file that exists, and every regular file below each named folder (no links); entries that do
// not exist are skipped. Throws if one of them is a path no student kit may hold (below).
std::vector<std::string> studentKitFiles(const std::filesystem::path& root);

// Paths that the student kit never holds, whatever the manifest says (a guard against a folder
// entry that is too wide): reference/, tests/oracles/, tests/submissions/, scenes/hidden/ and
// the exact 4MSM framework/numerics/msm_exact.cpp.
bool neverInStudentKit(const std::string& rel);

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
