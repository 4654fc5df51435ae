// rubric.h: the instructor-editable weights, thresholds and tolerances (grader/rubric.json),
// validated like a scene file (unknown keys, wrong types, values out of range: an error that
// names the file, the JSON path and what was expected), and the points each test is worth.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace sl::grader {

// Every value comes from a rubric file: defaultRubric() is grader/rubric.json as it was when
// the program was built (one source for the defaults), and a rubric file overrides it key by key.
struct Rubric {
    double total = 0.0;
    std::map<std::string, double> weights;  // stage -> points (before normalising to total)
    double passFraction = 0.0;  // at or above: full points
    double zeroFraction = 0.0;  // at or below: none; linear in between
    // moments stage (and the relativeDepth ladder); gaussian and sat ("filter"): tolerances
    // derived from the spread of correct variants (docs/grading.md).
    double momentsAbs = 0.0, momentsRel = 0.0, satRounding = 0.0;
    double filterAbs = 0.0, filterRel = 0.0;
    // sat on a per-pixel scene: satKernelTexels' widths, in texels (sat_kernel_ladder.h).
    double satKernelAbs = 0.0, satKernelRel = 0.0;
    double shadowTol = 0.0, finalTol = 0.0;
    std::string visibility;
    std::string hiddenVisibility;
    // "both": the gaussian and sat stages are graded on the scenes that use them (default);
    // "either": their points are pooled and go to the filter the submission implements
    // (the better one when it has both): the course handout lets students choose.
    std::string filters;

    // Per-stage ramps that replace the two above (final: see docs/grading.md).
    std::map<std::string, std::pair<double, double>> stageRamp;  // stage -> (pass, zero)

    // Worst-texel rule (moment-map stages): a texel off by more than worstTexelFactor times
    // its tolerance caps the test at worstTexelCap[stage] of its points, however few texels
    // are off: a border or edge bug touches few texels but is a bug (docs/grading.md).
    double worstTexelFactor = 0.0;
    std::map<std::string, double> worstTexelCap;  // stage -> cap; absent: no cap

    // Points for a stage's pass fraction, out of `max`.
    double points(const std::string& stage, double fraction, double max) const;
    std::pair<double, double> ramp(const std::string& stage) const;  // (pass, zero)

    // The points of every stage in `stages` (the stages with a test in this run), in exact
    // hundredths: weights rescaled to `total`, rounded, the rounding remainder given one
    // hundredth at a time to the stages with the largest remainders (ties: stage order).
    // The result sums to `total` exactly.
    std::map<std::string, long> stageHundredths(const std::vector<std::string>& stages) const;
};

// The default rubric: grader/rubric.json built into the program (rubric_defaults.cpp.in), so a
// kit without the file grades the same way.
Rubric defaultRubric();

// Reads the rubric; a missing file gives the documented defaults, a broken or invalid one
// throws std::runtime_error("<file>: /json/path: expected ...").
Rubric loadRubric(const std::filesystem::path& path);

// Splits `hundredths` into `n` parts that differ by at most one hundredth, the larger ones
// first: the points of the n tests of one stage. Sums to `hundredths` exactly.
std::vector<long> splitHundredths(long hundredths, int n);

}  // namespace sl::grader
