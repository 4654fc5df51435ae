// batch.h: grading a folder of submissions (`shadowlab grade --batch DIR -j N`), whole, as one
// shard of N (a Slurm array's task), or only merging what the shards graded.
#pragma once

#include "grader.h"

namespace sl::grader {

struct BatchOptions {
    fs::path dir;               // one subfolder per submission (names starting with '.' skipped)
    int parallel = 1;           // submissions at a time
    int shard = 1, shards = 1;  // --shard K/N: the K-th of every N submissions in name order
    bool mergeOnly = false;     // --merge: grade nothing, write the gradebook of what is stored
};

struct BatchOutcome {
    size_t submissions = 0;            // in DIR
    size_t graded = 0, reused = 0;     // this run's share: graded now, or stored already
    std::vector<std::string> missing;  // no row under its digest (another shard's, or stopped)
    bool wroteGradebook = false;       // scores.csv, index.html, class.html (not for a shard)
    std::vector<double> cpuSeconds;    // user + sys of each submission graded now (its processes)
    double referenceCpuSeconds = 0.0;  // the reference's renders, when they were made now
};

// Grades each subfolder of DIR into OUT/<name>/ (results.json, report/, row.json), N at a
// time, with a progress bar on stderr. A submission whose stored row has the digest of its
// folder's bytes and of this setup (batch_store.h) is not graded again, so a batch stopped in
// any way and started again grades only what is missing and gives the same scores. Each row is
// stored as its submission ends. Then (unless a shard of several) writes the gradebook
// (gradebook.h) of every submission. Each submission is graded by its own child process (a
// fork of the batch running gradeAndPrint, or `shadowlab grade` exec'd), so that nothing one
// submission does (a crash of the grader itself included) can cost another its grade.
BatchOutcome gradeBatch(const BatchOptions& batch, const GradeOptions& base);

// What `shadowlab grade --submission` does once its options are read: grades, prints the score
// table and where the results are on stdout, the visible warnings on stderr. Returns the exit
// code (0: a results.json with scores; 1: the grader failed, results.json says why). A batch's
// children run this in a fork of the batch, or exec'd through the command line.
int gradeAndPrint(const GradeOptions& options);

// The row of scores.csv for a grade: the points per stage, the tests short of full marks, the
// visible warnings as notes (those about hidden scenes counted, not named), or the reason the
// grader failed.
BatchRow batchRow(const GradeSummary& summary);

}  // namespace sl::grader
