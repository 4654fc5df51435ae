// rubric.h: the instructor-editable weights, thresholds and tolerances (grader/rubric.json).
#pragma once

#include <filesystem>
#include <map>
#include <string>

namespace sl::grader {

struct Rubric {
    double total = 100.0;
    std::map<std::string, double> weights;  // stage -> points (before normalising to total)
    double passFraction = 0.995;  // at or above: full points
    double zeroFraction = 0.90;   // at or below: none; linear in between
    double momentsAbs = 1e-4, momentsRel = 1e-3, satRounding = 8.0;
    double shadowTol = 0.02, finalTol = 0.02;
    std::string visibility = "visible";
    std::string hiddenVisibility = "after_due_date";

    // Per-stage ramps that replace the two above (final: see docs/grading.md).
    std::map<std::string, std::pair<double, double>> stageRamp;  // stage -> (pass, zero)

    // Points for a stage's pass fraction, out of `max`.
    double points(const std::string& stage, double fraction, double max) const;
    std::pair<double, double> ramp(const std::string& stage) const;  // (pass, zero)
};

// Reads the rubric; a missing file gives the documented defaults, a broken one throws.
Rubric loadRubric(const std::filesystem::path& path);

}  // namespace sl::grader
