// points.h: what each test is worth and earns, in exact hundredths, and the rubric's filter
// mode. A stage's points (weights rescaled to the rubric's total, largest remainder) are
// split over its tests, the remainder deterministically to the first ones, so the maxima
// add up to the total exactly; a test that lost anything shows at least 0.01 less than its
// maximum, so the displayed points, the status and the totals always agree.
#pragma once

#include "grader.h"
#include "rubric.h"

namespace sl::grader {

// Turns every test's `fraction` into `score` and `maxScore`, sets the summary's totals,
// filterMode and notes. With rubric.filters == "either", the gaussian and sat points are
// pooled and go to the filter stage with the better result (the other stage's tests, and the
// `final` tests of the scenes that use it, are left out; notes say so).
void assignPoints(GradeSummary& summary, const Rubric& rubric);

// The filter stage the "either" mode keeps: the better mean fraction of its tests (gaussian on
// a tie), the only one with tests, or "" when there is no filter test.
std::string betterFilter(const std::vector<TestResult>& tests);

// The points in hundredths a test earns for `fraction` of `maxHundredths`: all of them only
// at fraction >= 1, else at most maxHundredths - 1.
long earnedHundredths(double fraction, long maxHundredths);

}  // namespace sl::grader
