// cli_probe: `shadowlab probe FUNCTION` — evaluates one stage function of a solution on the
// rows of a CSV file, in one compute dispatch with exactly the renderer's GLSL (probe.h),
// and writes the same rows with the results appended. `--generate NAME` writes a named case
// set's inputs instead (probe_cases.h). The help text below is the user documentation.
#include "cli_commands.h"
#include "depth_ladder.h"
#include "gl_context.h"
#include "image_io.h"
#include "msm_robustness.h"
#include "paths.h"
#include "probe.h"
#include "probe_cases.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>

namespace sl::cli {
namespace {

const char* kProbeHelp = R"(Evaluates a stage function of a solution on every row of a CSV file.

FUNCTION and its CSV columns (a header row names them; any other columns, e.g. a case
name, pass through unchanged; the results are appended as the last columns):
  msm         m1,m2,m3,m4,zf -> G
              G = momentShadowIntensity(vec4(m1..m4), zf) with uMomentBias = --alpha.
              The reference biases the moments toward the vector (0.5, 0.5, 0.5, 0.5)
              (two equal point masses at depths 0 and 1): b' = (1 - a)*b + a*0.5,
              with a = 3e-5 by default (float32 moments).
  moments     lightDepth,near,far -> b1,b2,b3,b4
              computeMoments(relativeDepth(lightDepth, vec2(near, far))).
  sat-lookup  cx,cy,w,h -> b1,b2,b3,b4, expected_b1..expected_b4, max_error (and
              texel_centres: yes when cx and cy are both texel centres i + 0.5, where the
              grader's sat stage evaluates every box; the handout asks for 1e-4)
              satBoxAverage(table, vec2(cx, cy), vec2(w, h)) where table is what the
              solution's sat.comp makes of the moment map (--map FILE, an RGBA EXR; or
              --map-size N, a smooth synthetic map: depth z = 0.6 + 0.3*(x + 2y)/(3N)
              + 0.02*sin(x/7)*cos(y/11), moments (z, z^2, z^3, z^4)). Texel units, texel
              i covers [i, i+1), y counts up from the bottom row (as GL stores it); the
              expected values are the exact (double) box means of that map.

--generate NAME writes a case set's inputs (to --out, or stdout) instead of probing:
  msm: the hard-case catalogue's sets (`catalogue` = all of them; columns case, m1..m4,
  zf, expected, bound, note; `expected` is the exact 4MSM value at --alpha, `bound` what
  a float32 implementation must meet; docs/numerics.md); `zf-ladder` = the fragment
  depths of the robustness stage's monotonicity check, per case, with the exact G.
  moments: `depth-ladder` (the grader's relativeDepth ladder: light depths in front of,
  inside and behind three depth ranges, with the exact moments).
  sat-lookup: `boxes` (sizes 1 .. N texels at the origin, the centre and the far corner,
  boxes across the map's border, fractional sizes; N = --map-size, or the --map's width).

Example:
  shadowlab probe msm --generate catalogue --out cases.csv
  shadowlab probe msm --solution student --input cases.csv --out results.csv)";

// A CSV error: "file:line: column 'name': message".
struct CsvError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct Table {
    std::vector<std::string> header;
    std::vector<std::vector<std::string>> rows;
    std::vector<int> lineOf;  // file line of each row (1-based; the header is line 1)
};

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

// The numeric columns `names` of every row, in that order.
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

// Writes the table with `added` columns appended (one vector of values per row).
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

Image syntheticMomentMap(int n) {
    Image img(n, n, 4);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const float z = 0.6f + 0.3f * float(x + 2 * y) / float(3 * n) +
                            0.02f * std::sin(x / 7.0f) * std::cos(y / 11.0f);
            for (int c = 0; c < 4; ++c) img.at(x, y, c) = std::pow(z, float(c + 1));
        }
    return img;
}

// The exact box mean of `map` over the box (centre c, size w × h, clipped to the map), in
// double: the value a sat-lookup must reproduce (to 1e-4, docs/numerics.md).
glm::dvec4 exactBoxMean(const Image& map, double cx, double cy, double w, double h) {
    const double x0 = std::clamp(cx - 0.5 * w, 0.0, double(map.width)), x1 = std::clamp(cx + 0.5 * w, 0.0, double(map.width));
    const double y0 = std::clamp(cy - 0.5 * h, 0.0, double(map.height)), y1 = std::clamp(cy + 0.5 * h, 0.0, double(map.height));
    glm::dvec4 sum(0.0);
    const double area = (x1 - x0) * (y1 - y0);
    if (!(area > 0)) return sum;
    for (int y = int(std::floor(y0)); y < int(std::ceil(y1)); ++y)
        for (int x = int(std::floor(x0)); x < int(std::ceil(x1)); ++x) {
            const double cover = (std::min(x1, x + 1.0) - std::max(x0, double(x))) *
                                 (std::min(y1, y + 1.0) - std::max(y0, double(y)));
            for (int c = 0; c < 4; ++c) sum[c] += cover * map.at(x, y, c);
        }
    return sum / area;
}

// "yes" when x and y are both texel centres (i + 0.5), as the grader's sat stage uses them.
std::string texelCentres(double x, double y) {
    auto centre = [](double v) { return v - std::floor(v) == 0.5; };
    return centre(x) && centre(y) ? "yes" : "no";
}

Table generate(const std::string& function, const std::string& name, int mapSize, float alpha) {
    Table t;
    if (function == "msm" && name == "zf-ladder") {
        // The robustness stage's monotonicity ladder of every hard case (msm_robustness.h).
        t.header = {"case", "m1", "m2", "m3", "m4", "zf", "expected"};
        for (const auto& c : msmHardCaseCatalogue(alpha))
            for (float z : msmMonotoneLadder(c))
                t.rows.push_back({c.name, csvNumber(c.b.x), csvNumber(c.b.y), csvNumber(c.b.z), csvNumber(c.b.w), csvNumber(z),
                                  csvNumber(exactMomentShadowIntensity(glm::dvec4(c.b), z, alpha))});
    } else if (function == "msm") {
        t.header = {"case", "m1", "m2", "m3", "m4", "zf", "expected", "bound", "note"};
        const auto cases = name == "catalogue" ? msmHardCaseCatalogue(alpha) : msmCaseSet(name, alpha);
        for (const auto& c : cases)
            t.rows.push_back({c.name, csvNumber(c.b.x), csvNumber(c.b.y), csvNumber(c.b.z), csvNumber(c.b.w), csvNumber(c.zf),
                              csvNumber(c.expected), csvNumber(c.bound), c.note});
    } else if (function == "moments" && name == "depth-ladder") {
        // The grader's relativeDepth ladder (depth_ladder.h), with the exact moments.
        t.header = {"lightDepth", "near", "far", "expected_b1", "expected_b2", "expected_b3", "expected_b4"};
        for (const glm::vec3& r : relativeDepthLadder()) {
            const glm::dvec4 m = exactLadderMoments(r);
            t.rows.push_back({csvNumber(r.x), csvNumber(r.y), csvNumber(r.z), csvNumber(m.x), csvNumber(m.y), csvNumber(m.z), csvNumber(m.w)});
        }
    } else if (function == "sat-lookup" && name == "boxes") {
        // Sizes 1 .. N at texel centres at the origin, the centre and the far corner; boxes
        // that cross the map's border; fractional sizes at fractional centres. Fits any N.
        t.header = {"cx", "cy", "w", "h", "texel_centres"};
        auto add = [&](double cx, double cy, double w, double h) {
            t.rows.push_back({csvNumber(cx), csvNumber(cy), csvNumber(w), csvNumber(h), texelCentres(cx, cy)});
        };
        const double n = mapSize;
        for (int s = 1; s <= mapSize; s *= 2)
            for (double c : {0.5 * s, 0.5 * std::floor(n / 2) * 2 + 0.5 * (mapSize % 2), n - 0.5 * s})
                add(std::floor(c) + 0.5, std::floor(c) + 0.5, s, s);
        for (double k : {7.0, 40.5})
            for (double c : {0.5, 1.5, std::floor(k / 2) + 0.5, n - 0.5, n - 1.5})
                add(std::min(c, n - 0.5), std::min(c, n - 0.5), k, k);
        for (double k : {2.5, 7.25, 40.5})
            add(std::min(0.37 * n, n - 0.25), std::min(0.61 * n, n - 0.25), k, k * 0.5 + 1);
    } else {
        throw std::invalid_argument("no case set '" + name + "' for " + function +
                                    " (msm: catalogue, zf-ladder or a set in `probe --help`; "
                                    "moments: depth-ladder; sat-lookup: boxes)");
    }
    for (auto& row : t.rows)  // no field may split into CSV fields (no quoting)
        for (auto& field : row)
            for (char& ch : field) if (ch == ',') ch = ';';
    return t;
}

struct ProbeArgs {
    std::string function, solution = defaultSolution(), input, out, generate, map;
    float alpha = kReferenceMomentBias;
    int mapSize = 1024;
};

int runProbe(const ProbeArgs& a, const std::string& backend) {
    if (!a.generate.empty()) {
        // With --map, the boxes fit that map.
        const int size = a.map.empty() || a.function != "sat-lookup" ? a.mapSize : readImage(a.map).width;
        writeCsv(a.out, generate(a.function, a.generate, size, a.alpha), {}, {});
        return Ok;
    }
    if (a.input.empty()) throw CsvError("probe: --input cases.csv is required (or --generate NAME)");
    const Table t = readCsv(a.input);
    auto context = createContext(parseBackendKind(backend));
    const ShaderLibrary library = ShaderLibrary::forSolution(resolveSolution(a.solution), repoRoot());
    std::vector<std::vector<double>> results;
    if (a.function == "msm") {
        const auto v = numericColumns(t, a.input, {"m1", "m2", "m3", "m4", "zf"});
        std::vector<glm::vec4> b;
        std::vector<float> zf;
        for (const auto& r : v) b.push_back({r[0], r[1], r[2], r[3]}), zf.push_back(r[4]);
        for (float g : probeMomentShadowIntensity(library, b, zf, a.alpha)) results.push_back({g});
        writeCsv(a.out, t, {"G"}, results);
        return Ok;
    }
    std::vector<glm::vec4> out;
    if (a.function == "moments") {
        std::vector<glm::vec3> in;
        for (const auto& r : numericColumns(t, a.input, {"lightDepth", "near", "far"}))
            in.push_back({r[0], r[1], r[2]});
        out = probeMoments(library, in);
    } else {
        std::vector<glm::vec4> boxes;
        for (const auto& r : numericColumns(t, a.input, {"cx", "cy", "w", "h"}))
            boxes.push_back({r[0], r[1], r[2], r[3]});
        Image map = a.map.empty() ? syntheticMomentMap(a.mapSize) : readImage(a.map);
        if (map.channels != 4) throw CsvError(a.map + ": the moment map must have 4 channels (RGBA)");
        out = probeSatBoxAverage(library, map, boxes);
        // Like probe msm's catalogue: the exact values next to the solution's, and whether the
        // box is centred on a texel centre (the grader's sat stage uses texel centres only).
        for (size_t i = 0; i < out.size(); ++i) {
            const glm::vec4 b = boxes[i];
            const glm::dvec4 want = exactBoxMean(map, b.x, b.y, b.z, b.w);
            double err = 0.0;
            for (int c = 0; c < 4; ++c)
                err = std::max(err, std::isfinite(out[i][c]) ? std::fabs(out[i][c] - want[c]) : INFINITY);
            results.push_back({out[i].x, out[i].y, out[i].z, out[i].w, want.x, want.y, want.z, want.w, err});
        }
        // Appended last: b1..b4, the exact means, max_error, and texel_centres (unless the
        // input has it already, as `--generate boxes` writes it).
        Table shown = t;
        const bool haveCentres =
            std::find(t.header.begin(), t.header.end(), "texel_centres") != t.header.end();
        for (const char* h : {"b1", "b2", "b3", "b4", "expected_b1", "expected_b2", "expected_b3",
                              "expected_b4", "max_error"})
            shown.header.push_back(h);
        if (!haveCentres) shown.header.push_back("texel_centres");
        for (size_t i = 0; i < shown.rows.size(); ++i) {
            for (double v : results[i]) shown.rows[i].push_back(csvNumber(v));
            if (!haveCentres) shown.rows[i].push_back(texelCentres(boxes[i].x, boxes[i].y));
        }
        writeCsv(a.out, shown, {}, {});
        return Ok;
    }
    for (const auto& m : out) results.push_back({m.x, m.y, m.z, m.w});
    writeCsv(a.out, t, {"b1", "b2", "b3", "b4"}, results);
    return Ok;
}

}  // namespace

void addProbeCommand(CLI::App& app, Context& ctx) {
    auto* probe = app.add_subcommand("probe", "evaluate a stage function on a CSV of inputs "
                                              "(msm, moments, sat-lookup)");
    probe->footer(kProbeHelp);
    auto a = std::make_shared<ProbeArgs>();
    probe->add_option("function", a->function, "msm, moments or sat-lookup")
        ->required()
        ->check(CLI::IsMember({"msm", "moments", "sat-lookup"}));
    probe->add_option("--solution", a->solution, "reference, student, or a folder of stage files");
    probe->add_option("--input", a->input, "input CSV (header row; columns per function, below)");
    probe->add_option("--out", a->out, "output CSV (default: stdout)");
    probe->add_option("--generate", a->generate, "write the inputs of a named case set instead");
    probe->add_option("--alpha", a->alpha, "moment bias uMomentBias (default 3e-5)");
    probe->add_option("--map", a->map, "sat-lookup: moment map (RGBA EXR)");
    probe->add_option("--map-size", a->mapSize, "sat-lookup: size of the synthetic map (default 1024)")
        ->check(CLI::Range(1, 8192));
    probe->callback([a, &ctx] {
        try {
            ctx.exitCode = runProbe(*a, ctx.backend);
        } catch (const CsvError& e) {
            std::cerr << "input error: " << e.what() << "\n";
            ctx.exitCode = BadInput;
        } catch (const std::invalid_argument& e) {
            std::cerr << "input error: " << e.what() << "\n";
            ctx.exitCode = BadInput;
        }
    });
}

}  // namespace sl::cli
