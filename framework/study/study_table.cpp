// study_table: the study's CSV (see study_table.h).
#include "study_table.h"

#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace sl {
namespace {

const std::vector<std::string>& columns() {
    static const std::vector<std::string> c = {
        "scene", "solution", "technique", "spec", "filter", "radius", "kernel_texels", "map_size",
        "light_size", "bits", "parameters", "map_bytes", "plan_bytes", "repeats",
        "frame_cost_min", "frame_cost_median", "frame_cost_max", "frame_wall_ms_median",
        "pass_cost", "copy_cost", "frame_over_copy", "cost_method",
        "truth_rmse", "truth_max", "truth_p99", "truth_over_0.05", "truth_leak_area",
        "truth_dark_area", "filtered_rmse", "filtered_max", "filtered_p99",
        "filtered_over_0.05", "filtered_leak_area", "filtered_dark_area", "pixels",
        "flicker_frames", "flicker", "flicker_truth", "reused",
        "map_key", "map_from", "image_sha256", "image", "error_map"};
    return c;
}

// Fields never hold commas or quotes except free text, which is quoted.
std::string quoted(const std::string& s) {
    std::string q = "\"";
    for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
}

std::vector<std::string> splitCsv(const std::string& line) {
    std::vector<std::string> out;
    std::string cur;
    bool inQuotes = false;
    for (size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (inQuotes) {
            if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') cur += '"', ++i;
            else if (c == '"') inQuotes = false;
            else cur += c;
        } else if (c == '"') {
            inQuotes = true;
        } else if (c == ',') {
            out.push_back(cur);
            cur.clear();
        } else {
            cur += c;
        }
    }
    out.push_back(cur);
    return out;
}

void errorFields(std::vector<std::string>& f, const ShadowError& e) {
    for (double v : {e.rmse, e.max, e.p99, e.over005, e.leakArea, e.darkArea}) f.push_back(formatNumber(v));
}

}  // namespace

std::string StudyRow::key() const {
    return scene + "|" + solution + "|" + spec + "|" + filter + "|" + std::to_string(radius) +
           "|" + std::to_string(mapSize) + "|light " + formatNumber(lightSize);
}

std::string formatNumber(double v, const char* format) {
    char b[40];
    std::snprintf(b, sizeof b, format, v);
    return b;
}

const std::string& studyCsvHeader() {
    static const std::string h = [] {
        std::string s;
        for (const auto& c : columns()) s += (s.empty() ? "" : ",") + c;
        return s;
    }();
    return h;
}

std::string toCsvLine(const StudyRow& r) {
    std::vector<std::string> f = {r.scene, r.solution, r.technique, quoted(r.spec), r.filter,
                                  std::to_string(r.radius), formatNumber(r.kernelTexels),
                                  std::to_string(r.mapSize), formatNumber(r.lightSize),
                                  std::to_string(r.bits), quoted(r.parameters),
                                  std::to_string(r.mapBytes), std::to_string(r.planBytes),
                                  std::to_string(r.repeats), formatNumber(r.frameMin),
                                  formatNumber(r.frameMedian), formatNumber(r.frameMax),
                                  formatNumber(r.frameWallMedian), quoted(r.passTimes),
                                  formatNumber(r.copyMillis), formatNumber(r.frameRatio),
                                  quoted(r.costMethod)};
    errorFields(f, r.truth);
    errorFields(f, r.filtered);
    f.push_back(std::to_string(r.truth.pixels));
    f.push_back(std::to_string(r.flickerFrames));
    f.push_back(formatNumber(r.flicker));
    f.push_back(formatNumber(r.flickerTruth));
    f.push_back(quoted(r.reused));
    f.push_back(quoted(r.mapKey));
    f.push_back(quoted(r.mapFrom));
    f.push_back(r.imageDigest);
    f.push_back(r.image);
    f.push_back(r.errorMap);
    std::string line;
    for (size_t i = 0; i < f.size(); ++i) line += (i ? "," : "") + f[i];
    return line;
}

std::vector<StudyRow> readStudyCsv(const fs::path& path) {
    std::vector<StudyRow> rows;
    std::ifstream in(path);
    if (!in) return rows;
    std::string line;
    int lineNo = 0;
    while (std::getline(in, line)) {
        ++lineNo;
        if (lineNo == 1) {
            if (line != studyCsvHeader())
                throw std::runtime_error(path.string() + ":1: not a study table of this version "
                                         "(expected the header " + studyCsvHeader() +
                                         "): delete it, or give the study another --out, to "
                                         "start afresh");
            continue;
        }
        if (line.empty()) continue;
        const auto f = splitCsv(line);
        // A row cut short by an interrupted write is dropped, and redone on resume.
        if (f.size() != columns().size()) continue;
        try {
            StudyRow r;
            size_t i = 0;
            r.scene = f[i++], r.solution = f[i++], r.technique = f[i++], r.spec = f[i++];
            r.filter = f[i++];
            r.radius = std::stoi(f[i++]);
            r.kernelTexels = std::stod(f[i++]);
            r.mapSize = std::stoi(f[i++]);
            r.lightSize = std::stod(f[i++]);
            r.bits = std::stoi(f[i++]);
            r.parameters = f[i++];
            r.mapBytes = std::stoull(f[i++]);
            r.planBytes = std::stoull(f[i++]);
            r.repeats = std::stoi(f[i++]);
            r.frameMin = std::stod(f[i++]), r.frameMedian = std::stod(f[i++]);
            r.frameMax = std::stod(f[i++]), r.frameWallMedian = std::stod(f[i++]);
            r.passTimes = f[i++];
            r.copyMillis = std::stod(f[i++]), r.frameRatio = std::stod(f[i++]);
            r.costMethod = f[i++];
            for (ShadowError* e : {&r.truth, &r.filtered}) {
                e->rmse = std::stod(f[i++]), e->max = std::stod(f[i++]);
                e->p99 = std::stod(f[i++]), e->over005 = std::stod(f[i++]);
                e->leakArea = std::stod(f[i++]), e->darkArea = std::stod(f[i++]);
            }
            r.truth.pixels = r.filtered.pixels = std::stoull(f[i++]);
            r.flickerFrames = std::stoi(f[i++]);
            r.flicker = std::stod(f[i++]), r.flickerTruth = std::stod(f[i++]);
            r.reused = f[i++], r.mapKey = f[i++], r.mapFrom = f[i++];
            r.imageDigest = f[i++], r.image = f[i++], r.errorMap = f[i++];
            rows.push_back(r);
        } catch (const std::logic_error&) {
            throw std::runtime_error(path.string() + ":" + std::to_string(lineNo) +
                                     ": expected a study row of numbers, found \"" + line + "\"");
        }
    }
    return rows;
}

void appendStudyRow(const fs::path& path, const StudyRow& row) {
    const bool fresh = !fs::exists(path) || fs::file_size(path) == 0;
    bool cutShort = false;  // an interrupted write left a line without its newline
    if (!fresh) {
        std::ifstream in(path, std::ios::binary);
        in.seekg(-1, std::ios::end);
        cutShort = in.get() != '\n';
    }
    std::ofstream out(path, std::ios::app);
    if (!out) throw std::runtime_error(path.string() + ": cannot write the study table");
    if (fresh) out << studyCsvHeader() << "\n";
    if (cutShort) out << "\n";
    out << toCsvLine(row) << "\n";
    out.flush();
}

void writeStudyCsv(const fs::path& path, const std::vector<StudyRow>& rows) {
    const fs::path tmp = path.string() + ".tmp";
    {
        std::ofstream out(tmp, std::ios::trunc);
        if (!out) throw std::runtime_error(tmp.string() + ": cannot write the study table");
        out << studyCsvHeader() << "\n";
        for (const StudyRow& r : rows) out << toCsvLine(r) << "\n";
    }
    fs::rename(tmp, path);  // whole or not at all
}

}  // namespace sl
