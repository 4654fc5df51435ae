// filter_benchmark: interleaved timing of copy, Gaussian and SAT passes (see the header).
#include "filter_benchmark.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <random>

namespace sl {
namespace {

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n == 0 ? 0.0 : (n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]));
}

double timeIt(const std::function<void()>& work) {
    gl::Finish();
    const auto start = std::chrono::steady_clock::now();
    work();
    gl::Finish();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

}  // namespace

BenchReport runFilterBenchmark(Renderer& r, int size, int repeats) {
    // Moments of random depths: realistic values, fixed seed.
    Image moments(size, size, 4);
    std::mt19937 rng(1234);
    std::uniform_real_distribution<float> depth(0.0f, 1.0f);
    for (int i = 0; i < size * size; ++i) {
        float z = depth(rng);
        float* p = &moments.pixels[size_t(i) * 4];
        p[0] = z, p[1] = z * z, p[2] = z * z * z, p[3] = z * z * z * z;
    }
    Texture src = Texture::create(size, size, GL_RGBA32F);
    Texture mid = Texture::create(size, size, GL_RGBA32F);
    Texture dst = Texture::create(size, size, GL_RGBA32F);
    src.upload(moments);

    struct Case {
        std::string name;
        std::function<void()> run;
        int copies;     // how many copy passes it is compared with
        double target;
    };
    std::vector<Case> cases;
    for (int radius : {4, 8, 16}) {
        const double target = radius == 8 ? 1.5 : 0.0;
        cases.push_back({"gaussian r=" + std::to_string(radius) + ", x",
                         [&, radius] { r.gaussianPass(src, dst, radius, 0.0f, {1, 0}); }, 1,
                         target});
        cases.push_back({"gaussian r=" + std::to_string(radius) + ", y",
                         [&, radius] { r.gaussianPass(src, dst, radius, 0.0f, {0, 1}); }, 1,
                         target});
    }
    cases.push_back({"sat, rows + columns",
                     [&] {
                         r.satPass(src, mid, {1, 0});
                         r.satPass(mid, dst, {0, 1});
                     },
                     2, 3.0});

    // Warm-up: compile the programs, fault in the textures.
    for (int i = 0; i < 2; ++i) {
        timeIt([&] { r.copyPass(src, dst); });
        for (auto& c : cases) timeIt(c.run);
    }
    std::vector<double> copyMs;
    std::vector<std::vector<double>> caseMs(cases.size());
    for (int rep = 0; rep < repeats; ++rep) {
        copyMs.push_back(timeIt([&] { r.copyPass(src, dst); }));
        for (size_t i = 0; i < cases.size(); ++i) caseMs[i].push_back(timeIt(cases[i].run));
    }

    BenchReport report;
    report.size = size;
    report.repeats = repeats;
    report.copyMedianMs = median(copyMs);
    report.rows.push_back({"copy", report.copyMedianMs, report.copyMedianMs, 1.0, 0.0});
    for (size_t i = 0; i < cases.size(); ++i) {
        BenchRow row;
        row.name = cases[i].name;
        row.medianMs = median(caseMs[i]);
        row.baselineMs = report.copyMedianMs * cases[i].copies;
        row.ratio = row.medianMs / row.baselineMs;
        row.target = cases[i].target;
        report.rows.push_back(row);
    }
    return report;
}

std::string formatBenchReport(const BenchReport& report) {
    std::string out;
    char line[256];
    std::snprintf(line, sizeof line,
                  "%d² RGBA32F, %d interleaved repeats, medians; ratio = pass / copy pass(es)\n\n",
                  report.size, report.repeats);
    out += line;
    out += "| pass | median ms | ratio | target |\n|---|---:|---:|---:|\n";
    for (const BenchRow& row : report.rows) {
        std::string target = row.target > 0 ? "≤ " + std::to_string(row.target).substr(0, 3) +
                                                   (row.ratio <= row.target ? " ✓" : " ✗")
                                            : "";
        std::snprintf(line, sizeof line, "| %s | %.2f | %.2f | %s |\n", row.name.c_str(),
                      row.medianMs, row.ratio, target.c_str());
        out += line;
    }
    return out;
}

std::string benchReportJson(const BenchReport& report) {
    nlohmann::json rows = nlohmann::json::array();
    for (const BenchRow& row : report.rows)
        rows.push_back({{"pass", row.name},
                        {"medianMs", row.medianMs},
                        {"baselineMs", row.baselineMs},
                        {"ratio", row.ratio},
                        {"target", row.target}});
    return nlohmann::json{{"size", report.size}, {"repeats", report.repeats}, {"rows", rows}}
        .dump(2);
}

}  // namespace sl
