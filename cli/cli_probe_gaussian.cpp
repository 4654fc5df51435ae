// cli_probe_gaussian: `shadowlab probe gaussian` — the solution's gaussian_blur.comp (one pass or
// both, x then y) on small RGBA maps given in a CSV (map,x,y,m1..m4), next to the contract's
// blur computed in double (gaussian_exact.h), with the worst error of each map.
#include "cli_probe.h"

#include "exit_codes.h"
#include "gaussian_cases.h"
#include "gaussian_exact.h"
#include "gl_context.h"
#include "probe.h"
#include "probe_csv.h"
#include "stage_functions.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>

namespace sl::cli {
namespace {

// One map of the input: its name, its texels, and the table row of each texel.
struct InputMap {
    std::string name;
    Image map;
    std::vector<size_t> rowOf;  // per texel (x + y·width): its row in the table
};

std::vector<InputMap> readMaps(const Table& t, const std::string& path) {
    const auto v = numericColumns(t, path, {"x", "y", "m1", "m2", "m3", "m4"});
    const int nameColumn = columnIndex(t, "map");
    std::vector<InputMap> maps;
    std::map<std::string, size_t> index;
    std::vector<std::vector<size_t>> rows;  // per map
    for (size_t r = 0; r < t.rows.size(); ++r) {
        const std::string name = nameColumn < 0 ? "map" : t.rows[r][size_t(nameColumn)];
        auto [it, fresh] = index.emplace(name, maps.size());
        if (fresh) maps.push_back({name, {}, {}}), rows.emplace_back();
        const float x = v[r][0], y = v[r][1];
        if (!(x >= 0 && y >= 0 && x == std::floor(x) && y == std::floor(y) && x < 8192 && y < 8192))
            throw CsvError(path + ":" + std::to_string(t.lineOf[r]) +
                           ": x and y must be whole texel indices in 0 .. 8191");
        rows[it->second].push_back(r);
    }
    for (size_t m = 0; m < maps.size(); ++m) {
        int w = 0, h = 0;
        for (size_t r : rows[m]) w = std::max(w, int(v[r][0]) + 1), h = std::max(h, int(v[r][1]) + 1);
        InputMap& in = maps[m];
        in.map = Image(w, h, 4);
        in.rowOf.assign(size_t(w) * h, SIZE_MAX);
        for (size_t r : rows[m]) {
            const size_t i = size_t(v[r][1]) * w + size_t(v[r][0]);
            if (in.rowOf[i] != SIZE_MAX)
                throw CsvError(path + ":" + std::to_string(t.lineOf[r]) + ": map '" + in.name + "' has texel (" +
                               csvNumber(v[r][0]) + ", " + csvNumber(v[r][1]) + ") twice (first on line " +
                               std::to_string(t.lineOf[in.rowOf[i]]) + ")");
            in.rowOf[i] = r;
            for (int c = 0; c < 4; ++c) in.map.pixels[i * 4 + c] = v[r][2 + size_t(c)];
        }
        for (size_t i = 0; i < in.rowOf.size(); ++i)
            if (in.rowOf[i] == SIZE_MAX)
                throw CsvError(path + ": map '" + in.name + "' (" + std::to_string(w) + "x" + std::to_string(h) +
                               ", from its largest x and y) has no row for texel (" + std::to_string(i % size_t(w)) +
                               ", " + std::to_string(i / size_t(w)) + "): every texel needs one");
    }
    return maps;
}

Table generatedMaps(const ProbeArgs& a) {
    int w = 0, h = 0;
    if (!a.size.empty()) {
        char x = 0, extra = 0;
        if (std::sscanf(a.size.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || x != 'x' || w < 1 || h < 1 ||
            w > 4096 || h > 4096)
            throw std::invalid_argument("--size " + a.size + ": expected WxH, e.g. 7x5 (1 .. 4096 each)");
    }
    Table t;
    t.header = {"map", "x", "y", "m1", "m2", "m3", "m4"};
    for (const GaussianCase& c : gaussianCases(a.generate, w, h))
        for (int y = 0; y < c.map.height; ++y)
            for (int x = 0; x < c.map.width; ++x)
                t.rows.push_back({c.name, std::to_string(x), std::to_string(y), csvNumber(c.map.at(x, y, 0)),
                                  csvNumber(c.map.at(x, y, 1)), csvNumber(c.map.at(x, y, 2)),
                                  csvNumber(c.map.at(x, y, 3))});
    return t;
}

}  // namespace

int runGaussianProbe(const ProbeArgs& a, const std::string& backend) {
    if (!a.generate.empty()) {
        writeCsv(a.out, generatedMaps(a), {}, {});
        return Ok;
    }
    if (a.input.empty())
        throw CsvError("probe gaussian: --input maps.csv is required (or --generate NAME)");
    const bool alongX = a.passes.find('x') != std::string::npos, alongY = a.passes.find('y') != std::string::npos;
    const int passes = int(alongX) + int(alongY);
    Table t = readCsv(a.input);
    const std::vector<InputMap> maps = readMaps(t, a.input);
    auto context = createContext(parseBackendKind(backend));
    const ShaderLibrary library = ShaderLibrary::forSolution(resolveSolution(a.solution), repoRoot());
    const std::string file = library.displayPath(library.resolve("gaussian_blur.comp"));

    std::vector<std::vector<double>> results(t.rows.size());
    std::string lines;
    size_t beyond = 0, stubs = 0;
    double worstAll = -1;
    std::string worstWhere;
    char buf[400];
    const char* channel[4] = {"b1", "b2", "b3", "b4"};
    for (const InputMap& in : maps) {
        const Image got = probeGaussianBlur(library, in.map, a.radius, a.sigma, alongX, alongY);
        const std::vector<double> want = exactGaussianBlur(in.map, a.radius, a.sigma, alongX, alongY);
        double maxAbs = 0;
        for (float v : in.map.pixels) maxAbs = std::max(maxAbs, double(std::fabs(v)));
        const double allowed = gaussianRoundingBound(a.radius, passes, maxAbs);
        bool stub = true;
        double worst = -1;
        size_t worstTexel = 0;
        int worstChannel = 0;
        for (size_t i = 0; i < in.rowOf.size(); ++i) {
            stub = stub && got.stubTexel(i);
            double err = 0;
            std::vector<double>& row = results[in.rowOf[i]];
            for (int c = 0; c < 4; ++c) row.push_back(got.pixels[i * 4 + c]);
            for (int c = 0; c < 4; ++c) {
                const double g = got.pixels[i * 4 + c], e = want[i * 4 + c];
                const double d = std::isfinite(g) ? std::fabs(g - e) : INFINITY;
                row.push_back(e);
                if (d > err) err = d;
                if (d > worst) worst = d, worstTexel = i, worstChannel = c;
            }
            row.push_back(err);
        }
        const int w = in.map.width;
        const std::string size = std::to_string(w) + "x" + std::to_string(in.map.height);
        const char* verdict = stub ? "not implemented yet (stub value -1)"
                              : worst <= allowed ? "ok" : "beyond float rounding";
        stubs += stub;
        beyond += !stub && !(worst <= allowed);
        std::snprintf(buf, sizeof buf, "  %-18s %-7s max error %9.3g at (%zu, %zu) %s; float rounding allows %.3g: %s\n",
                      in.name.c_str(), size.c_str(), worst, worstTexel % size_t(w), worstTexel / size_t(w),
                      channel[worstChannel], allowed, verdict);
        lines += buf;
        if (!stub && worst > worstAll) {
            worstAll = worst;
            std::snprintf(buf, sizeof buf, "%s at (%zu, %zu) %s", in.name.c_str(), worstTexel % size_t(w),
                          worstTexel / size_t(w), channel[worstChannel]);
            worstWhere = buf;
        }
    }
    writeCsv(a.out, t, {"b1", "b2", "b3", "b4", "expected_b1", "expected_b2", "expected_b3", "expected_b4", "max_error"},
             results);

    std::ostream& report = a.out.empty() ? std::cerr : std::cout;
    const double sigma = a.radius <= 0 ? 0.0 : a.sigma > 0 ? a.sigma : a.radius / 2.0;
    std::snprintf(buf, sizeof buf, "gaussian: %s, radius %d, sigma %g, %s; expected: the same blur in double "
                  "(w_k ∝ exp(-k²/2σ²), w0 + 2·Σw_k = 1, clamp to edge)\n",
                  file.c_str(), a.radius, sigma, alongX && alongY ? "passes x then y" : alongX ? "pass x only" : "pass y only");
    report << buf << lines;
    if (stubs == maps.size())
        report << stubNoteText(file, StageFunction::GaussianPass) << "\n";
    else if (beyond == 0 && stubs == 0)
        report << "every map within float rounding of the exact blur (worst " << csvNumber(worstAll) << ")\n";
    else {
        std::snprintf(buf, sizeof buf, "%zu of %zu maps beyond float rounding%s (worst %.3g: %s)\n", beyond,
                      maps.size(), stubs ? (", " + std::to_string(stubs) + " all stub values").c_str() : "",
                      worstAll, worstWhere.c_str());
        report << buf;
    }
    return Ok;
}

}  // namespace sl::cli
