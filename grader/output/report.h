// report.h: the HTML report, OUT/report/index.html plus its PNGs (a self-contained folder that
// may be forwarded to a student), and, when hidden scenes were graded, OUT/report-staff/ for
// the course staff (every test, hidden ones marked; it links the public images in ../report/).
#pragma once

#include "grader.h"
#include "metrics.h"
#include "report_diagnosis.h"

#include <filesystem>
#include <string>
#include <vector>

namespace sl::grader {

// An image's preview, as the report shows it and as the goldens' PNGs hold it: every step-th
// texel, the step the smallest that brings the long side to at most 512.
Image previewImage(const Image& image);

class ReportWriter {
public:
    // `dir` is OUT/report; the staff report goes to dir's sibling "report-staff".
    explicit ReportWriter(std::filesystem::path dir);
    // Writes the reference, student and difference PNGs of one compared image: previews at
    // most 512 wide, and full-size ones for an image outside tolerance (a one-texel border
    // error disappears in a preview). A hidden test's images go to the staff folder only.
    void add(const TestResult& test, const std::string& image, const Image& reference,
             const Image& student, const Comparison& comparison);
    // The same, with the image's findings already made (findImageProblems, as scoreRender has).
    void add(const TestResult& test, const std::string& image, const Image& reference,
             const Image& student, const Comparison& comparison, const ImageFindings& findings);
    void finish(const GradeSummary& summary);  // index.html (and the staff page)

    // The page for `summary` (tests scored), student-visible (no hidden test) or staff.
    std::string page(const GradeSummary& summary, bool staff) const;

private:
    struct Entry {
        std::string scene, stage, image;
        bool hidden = false;
        std::string ref, student, diff;           // previews, relative to the entry's folder
        std::string refFull, studentFull, diffFull;  // full size ("" : the preview is full size)
        nlohmann::json metrics;
    };
    std::filesystem::path dir_, staffDir_;
    std::vector<Entry> entries_;
    std::vector<ImageFindings> findings_;
};

}  // namespace sl::grader
