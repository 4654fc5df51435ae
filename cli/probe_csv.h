// probe_csv: the CSV tables `shadowlab probe` reads and writes (a header row, plain fields: no
// quoting), with errors that name the file, line and column.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace sl::cli {

// A CSV error: "file:line: column 'name': message" (exit code 2).
struct CsvError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct Table {
    std::vector<std::string> header;
    std::vector<std::vector<std::string>> rows;
    std::vector<int> lineOf;  // file line of each row (1-based; the header is line 1)
};

Table readCsv(const std::string& path);

// The index of column `name`, or -1.
int columnIndex(const Table& t, const std::string& name);

// The numeric columns `names` of every row, in that order.
std::vector<std::vector<float>> numericColumns(const Table& t, const std::string& path,
                                               const std::vector<std::string>& names);

std::string csvNumber(double v);  // %.9g: a float round-trips

// Writes the table with `added` columns appended (one vector of values per row), to `path`,
// or to stdout when it is empty.
void writeCsv(const std::string& path, const Table& t, const std::vector<std::string>& added,
              const std::vector<std::vector<double>>& values);

// Replaces every ',' of every field by ';' (no field may split into CSV fields).
void sanitizeFields(Table& t);

}  // namespace sl::cli
