// probe_csv: the probe's CSV tables (see the header).
#include "probe_csv.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>

namespace sl::cli {
namespace {

std::vector<std::string> splitFields(const std::string& line) {
    std::vector<std::string> fields;
    std::stringstream ss(line);
    std::string f;
    while (std::getline(ss, f, ',')) fields.push_back(f);
    if (!line.empty() && line.back() == ',') fields.emplace_back();
    return fields;
}

std::string trim(const std::string& s) {
    const size_t a = s.find_first_not_of(" \t\r"), b = s.find_last_not_of(" \t\r");
    return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

}  // namespace

Table readCsv(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw CsvError(path + ": cannot open the input file");
    Table t;
    std::string line;
    int lineNo = 0;
    while (std::getline(in, line)) {
        ++lineNo;
        if (trim(line).empty()) continue;
        auto fields = splitFields(line);
        for (auto& f : fields) f = trim(f);
        if (t.header.empty()) {
            t.header = fields;
            continue;
        }
        if (fields.size() != t.header.size())
            throw CsvError(path + ":" + std::to_string(lineNo) + ": " + std::to_string(fields.size()) +
                           " fields, but the header has " + std::to_string(t.header.size()));
        t.rows.push_back(fields);
        t.lineOf.push_back(lineNo);
    }
    if (t.header.empty()) throw CsvError(path + ":1: empty file (a header row is required)");
    return t;
}

int columnIndex(const Table& t, const std::string& name) {
    for (size_t i = 0; i < t.header.size(); ++i)
        if (t.header[i] == name) return int(i);
    return -1;
}

std::vector<std::vector<float>> numericColumns(const Table& t, const std::string& path,
                                               const std::vector<std::string>& names) {
    std::vector<int> index;
    for (const auto& n : names) {
        int found = -1;
        for (size_t i = 0; i < t.header.size(); ++i)
            if (t.header[i] == n) found = int(i);
        if (found < 0) {
            std::string all;
            for (const auto& m : names) all += (all.empty() ? "" : ",") + m;
            throw CsvError(path + ":1: column '" + n + "' is missing (this function needs " + all + ")");
        }
        index.push_back(found);
    }
    std::vector<std::vector<float>> values;
    for (size_t r = 0; r < t.rows.size(); ++r) {
        std::vector<float> v;
        for (size_t k = 0; k < names.size(); ++k) {
            const std::string& s = t.rows[r][size_t(index[k])];
            char* end = nullptr;
            const float x = std::strtof(s.c_str(), &end);
            if (s.empty() || *end != '\0')
                throw CsvError(path + ":" + std::to_string(t.lineOf[r]) + ": column '" + names[k] +
                               "' (column " + std::to_string(index[k] + 1) + "): '" + s +
                               "' is not a number");
            v.push_back(x);
        }
        values.push_back(std::move(v));
    }
    return values;
}

std::string csvNumber(double v) {
    char buf[48];
    std::snprintf(buf, sizeof buf, "%.9g", v);
    return buf;
}

void writeCsv(const std::string& path, const Table& t, const std::vector<std::string>& added,
              const std::vector<std::vector<double>>& values) {
    std::ofstream fileOut;
    if (!path.empty()) {
        fileOut.open(path);
        if (!fileOut) throw std::runtime_error(path + ": cannot write the output file");
    }
    std::ostream& out = path.empty() ? std::cout : fileOut;
    auto line = [&](const std::vector<std::string>& fields) {
        for (size_t i = 0; i < fields.size(); ++i) out << (i ? "," : "") << fields[i];
        out << "\n";
    };
    std::vector<std::string> head = t.header;
    head.insert(head.end(), added.begin(), added.end());
    line(head);
    for (size_t r = 0; r < t.rows.size(); ++r) {
        std::vector<std::string> row = t.rows[r];
        if (r < values.size())
            for (double v : values[r]) row.push_back(csvNumber(v));
        line(row);
    }
}

void sanitizeFields(Table& t) {
    for (auto& row : t.rows)
        for (auto& field : row)
            for (char& ch : field) if (ch == ',') ch = ';';
}

}  // namespace sl::cli
