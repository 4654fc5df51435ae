// gradebook.h: what a batch hands the course: OUT/scores.csv (one row per student, the form
// gradebooks import), OUT/index.html (every student, a link to each report) and OUT/class.html
// (the class at a glance: a histogram per stage, the tests most often lost). All three are made
// from the stored rows alone, so a merge of shards writes the same files as one process.
#pragma once

#include "grader.h"

#include <optional>

namespace sl::grader {

struct GradebookEntry {
    std::string name;              // the submission's folder: the student's id
    std::optional<BatchRow> row;   // none: not graded (yet) under this setup
};

// scores.csv: student,total,max,<one column per stage>,lost,notes. A student not graded has
// empty points and "not graded" in notes, never a zero that a gradebook would take for a grade.
std::string scoresCsv(const std::vector<GradebookEntry>& entries);

// index.html: one row per student, linking OUT/<name>/report/index.html and results.json.
std::string indexPage(const std::vector<GradebookEntry>& entries);

// class.html: the total's and each stage's histogram (inline SVG) and the most often lost tests.
std::string classPage(const std::vector<GradebookEntry>& entries);

// Writes the three files into `out` (each through a fresh file and a rename).
void writeGradebook(const fs::path& out, const std::vector<GradebookEntry>& entries);

}  // namespace sl::grader
