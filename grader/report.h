// report.h: the HTML report, OUT/report/index.html plus its PNGs (a self-contained folder).
#pragma once

#include "grader.h"
#include "metrics.h"

#include <filesystem>
#include <string>
#include <vector>

namespace sl::grader {

class ReportWriter {
public:
    explicit ReportWriter(std::filesystem::path dir);
    // Writes the reference, student and difference PNGs of one compared image.
    void add(const TestResult& test, const std::string& image, const Image& reference,
             const Image& student, const Comparison& comparison);
    void finish(const GradeSummary& summary);  // index.html

private:
    struct Entry {
        std::string scene, stage, image, ref, student, diff;
        nlohmann::json metrics;
    };
    std::filesystem::path dir_;
    std::vector<Entry> entries_;
};

}  // namespace sl::grader
