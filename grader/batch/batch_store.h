// batch_store.h: what a batch remembers between runs. Each graded submission leaves
// OUT/<name>/row.json, written atomically once its results.json and report are complete, with
// the digest of what was graded: the submission folder's bytes and the setup (grader, rubric,
// scenes, reference, limits). A batch started again, after a stop of any kind, regrades only
// the submissions whose row is missing, unreadable or of another digest.
#pragma once

#include "grader.h"

#include <optional>

namespace sl::grader {

// SHA-256 over every file under `dir` (relative path, size and bytes, in path order; a link's
// target text, never followed). A file over 64 MiB counts by its size and modification time.
std::string submissionDigest(const fs::path& dir);

// SHA-256 over what decides a grade besides the submission: this executable, the rubric, each
// scene file, the reference's files (live) or the goldens (golden), the limits and backend.
std::string setupDigest(const GradeOptions& options);

// The digest a row is stored under: one submission under one setup.
std::string rowDigest(const std::string& submission, const std::string& setup);

fs::path rowPath(const fs::path& out, const std::string& name);

// The row stored for `name` if it was graded under `digest`; nullopt otherwise.
std::optional<BatchRow> storedRow(const fs::path& out, const std::string& name, const std::string& digest);

// Writes OUT/<name>/row.json through a fresh file and a rename (out_guard.h).
void storeRow(const fs::path& out, const std::string& name, const BatchRow& row);

}  // namespace sl::grader
