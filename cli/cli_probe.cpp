// cli_probe: `shadowlab probe FUNCTION` — evaluates one stage function of a solution on the
// rows of a CSV file, in one compute dispatch with exactly the renderer's GLSL (probe.h),
// and writes the same rows with the results appended. `--generate NAME` writes a named case
// set's inputs instead (probe_cases.h). The help text below is the user documentation.
#include "cli_commands.h"
#include "cli_probe.h"
#include "depth_ladder.h"
#include "gl_context.h"
#include "image_io.h"
#include "msm_robustness.h"
#include "paths.h"
#include "probe.h"
#include "probe_cases.h"
#include "probe_csv.h"
#include "rubric.h"
#include "stage_functions.h"
#include "stub_survey.h"

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
  gaussian    [map,]x,y,m1,m2,m3,m4 -> b1,b2,b3,b4, expected_b1..expected_b4, max_error
              Each map (the rows with the same `map`; without that column the whole file
              is one map) is an RGBA image, one row per texel (x, y from 0; every texel
              once; y counts up from the bottom row). The solution's gaussian_blur.comp
              runs on it as a render runs it: --passes xy (along x, then along y; default),
              x or y, with --radius r (default 4) and --sigma (default r/2). The expected
              values are the contract's blur in double (w_k ~ exp(-k^2/2 sigma^2),
              w0 + 2*sum w_k = 1, clamp to edge). A summary (stderr, or stdout with --out)
              gives each map's worst error against what float rounding allows,
              passes*(2r + 3)*2^-24*max|m|, and names a stub (-1) "not implemented yet".

msm --sweep: the property sweep (docs/numerics.md): 250 000 generated moment vectors
  (--vectors, --seed) x 4 fragment depths, in one dispatch, checked against bounds every
  correct G meets and that need no 4MSM solver: G finite and in [0, 1], monotone in zf,
  ~0 in front of every occluder, within the mean/variance (Cantelli) bounds. It prints a
  summary and the first failures; --out writes every failing case (columns check,
  m1..m4, zf, G, bound: `probe msm --input` takes that file back).

--generate NAME writes a case set's inputs (to --out, or stdout) instead of probing:
  msm: the hard-case catalogue's sets (`catalogue` = all of them; columns case, m1..m4,
  zf, expected, bound, note; `expected` is the exact 4MSM value at --alpha, `bound` what
  a float32 implementation must meet; docs/numerics.md); `zf-ladder` = the fragment
  depths of the robustness stage's monotonicity check, per case, with the exact G.
  moments: `depth-ladder` (the grader's relativeDepth ladder: light depths in front of,
  inside and behind three depth ranges, with the exact moments).
  sat-lookup: `boxes` (sizes 1 .. N texels at the origin, the centre and the far corner,
  boxes across the map's border, fractional sizes; N = --map-size, or the --map's width).
  gaussian: `impulse`, `edge` (a step at each border, one per channel), `constant`,
  `random`, or `all`: maps at 7x5, 67x3, 3x67 and 1x1 (work groups partly outside the
  image), or at --size WxH only.

Example:
  shadowlab probe msm --generate catalogue --out cases.csv
  shadowlab probe msm --solution student --input cases.csv --out results.csv
  shadowlab probe gaussian --generate all --out maps.csv
  shadowlab probe gaussian --solution student --input maps.csv --radius 4 --out blurred.csv
  shadowlab probe msm --solution student --sweep)";

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
                                    "moments: depth-ladder; sat-lookup: boxes; gaussian: "
                                    "impulse, edge, constant, random, all)");
    }
    sanitizeFields(t);  // no field may split into CSV fields (no quoting)
    return t;
}

// The probe's verdict on msm rows that carry the exact G and its bound (`--generate`'s
// catalogue and sets): how many are beyond it, and the worst; the stub note for a stub.
void printMsmVerdict(std::ostream& o, const ShaderLibrary& library, const Table& t,
                     const std::vector<std::vector<double>>& g) {
    const std::string file = library.displayPath(library.resolve("msm.glsl"));
    const int expected = columnIndex(t, "expected"), bound = columnIndex(t, "bound"), name = columnIndex(t, "case");
    if (!g.empty() && std::all_of(g.begin(), g.end(), [](const auto& r) { return r[0] == -1.0; })) {
        o << stubNoteText(file, StageFunction::MomentShadowIntensity) << "\n";
        return;
    }
    if (expected < 0 || bound < 0) {
        o << file << ": " << g.size() << " cases evaluated (no expected and bound columns to check them "
          << "against: `probe msm --generate catalogue` writes them)\n";
        return;
    }
    size_t beyond = 0, invalid = 0, worst = 0;
    double worstRatio = -1.0;
    for (size_t i = 0; i < g.size(); ++i) {
        const double v = g[i][0], e = std::stod(t.rows[i][size_t(expected)]), b = std::stod(t.rows[i][size_t(bound)]);
        const double ratio = std::isfinite(v) ? std::fabs(v - e) / std::max(b, 1e-30) : INFINITY;
        invalid += !std::isfinite(v) || v < 0.0 || v > 1.0;
        beyond += ratio > 1.0;
        if (ratio > worstRatio) worstRatio = ratio, worst = i;
    }
    o << file << ": momentShadowIntensity on " << g.size() << " cases: ";
    if (beyond == 0 && invalid == 0) {
        o << "every G within its case's bound of the exact value (worst " << csvNumber(worstRatio) << "x its bound)\n";
        return;
    }
    o << beyond << " beyond their bound of the exact value, " << invalid << " NaN, Inf or outside [0, 1]; worst: "
      << (name >= 0 ? t.rows[worst][size_t(name)] : "row " + std::to_string(worst + 1)) << ", G = " << csvNumber(g[worst][0])
      << ", expected " << t.rows[worst][size_t(expected)] << " +- " << t.rows[worst][size_t(bound)] << "\n";
}

// The probe's verdict on moments rows that carry the exact moments (`--generate depth-ladder`),
// within the grader's moments tolerance (grader/rubric.json), and the stub notes.
void printMomentsVerdict(std::ostream& o, const ShaderLibrary& library, const Table& t,
                         const std::vector<std::vector<double>>& b) {
    const std::string file = library.displayPath(library.resolve("moments.glsl"));
    if (!b.empty() && std::all_of(b.begin(), b.end(), [](const auto& r) { return r[0] == -1.0 && r[1] == -1.0; })) {
        o << stubNoteText(file, StageFunction::ComputeMoments) << "\n";
        return;
    }
    if (!b.empty() && std::all_of(b.begin(), b.end(), [](const auto& r) { return r[0] == -1.0; })) {
        o << stubNoteText(file, StageFunction::RelativeDepth) << "\n";
        return;
    }
    int expected[4];
    for (int c = 0; c < 4; ++c) expected[c] = columnIndex(t, "expected_b" + std::to_string(c + 1));
    if (std::any_of(expected, expected + 4, [](int i) { return i < 0; })) {
        o << file << ": " << b.size() << " light depths evaluated (no expected_b1..b4 columns to check them "
          << "against: `probe moments --generate depth-ladder` writes them)\n";
        return;
    }
    const grader::Rubric rubric = grader::loadRubric(repoRoot() / "grader/rubric.json");
    size_t off = 0, worst = 0;
    double worstRatio = -1.0;
    for (size_t i = 0; i < b.size(); ++i) {
        double ratio = 0.0;
        for (int c = 0; c < 4; ++c) {
            const double e = std::stod(t.rows[i][size_t(expected[c])]), v = b[i][size_t(c)];
            const double r = std::isfinite(v) ? std::fabs(v - e) / (rubric.momentsAbs + rubric.momentsRel * std::fabs(e)) : INFINITY;
            ratio = std::max(ratio, r);
        }
        off += ratio > 1.0;
        if (ratio > worstRatio) worstRatio = ratio, worst = i;
    }
    o << file << ": computeMoments(relativeDepth(...)) on " << b.size() << " light depths: ";
    if (off == 0) {
        o << "every moment within " << rubric.momentsAbs << " + " << rubric.momentsRel << "·|exact| (the grader's "
          << "tolerance; worst " << csvNumber(worstRatio) << "x it)\n";
        return;
    }
    auto at = [&](const char* column) { return t.rows[worst][size_t(columnIndex(t, column))]; };
    o << off << " off by more than " << rubric.momentsAbs << " + " << rubric.momentsRel << "·|exact|; worst: row "
      << worst + 1 << " (lightDepth " << at("lightDepth") << ", near " << at("near") << ", far " << at("far")
      << "), " << csvNumber(worstRatio) << "x the tolerance\n";
}

// The probe's verdict on sat-lookup rows (each with its exact box mean): how many are off by
// more than the grader's sat tolerance (grader/rubric.json), and the worst box. The table comes
// from the solution's sat.comp, so a stub there is named first: the lookup reads its -1s.
void printSatLookupVerdict(std::ostream& o, const ShaderLibrary& library, const std::vector<glm::vec4>& boxes,
                           const std::vector<std::vector<double>>& r) {
    const std::vector<StageFunction> stubs =
        stubFunctions(library, {StageFunction::SatPass, StageFunction::SatBoxAverage});
    for (StageFunction f : stubs)
        o << stubNoteText(library.displayPath(library.resolve(stageFunction(f).file)), f) << "\n";
    if (!stubs.empty()) return;
    const grader::Rubric rubric = grader::loadRubric(repoRoot() / "grader/rubric.json");
    size_t off = 0, offCentred = 0, worst = 0;
    double worstRatio = -1.0;
    for (size_t i = 0; i < r.size(); ++i) {
        double ratio = 0.0;
        for (int c = 0; c < 4; ++c) {
            const double v = r[i][size_t(c)], e = r[i][size_t(c + 4)];
            ratio = std::max(ratio, std::isfinite(v) ? std::fabs(v - e) / (rubric.filterAbs + rubric.filterRel * std::fabs(e))
                                                     : INFINITY);
        }
        off += ratio > 1.0;
        offCentred += ratio > 1.0 && texelCentres(boxes[i].x, boxes[i].y) == "yes";
        if (ratio > worstRatio) worstRatio = ratio, worst = i;
    }
    o << library.displayPath(library.resolve("sat_lookup.glsl")) << ": satBoxAverage on " << r.size()
      << " boxes (over the table of " << library.displayPath(library.resolve("sat.comp")) << "): ";
    if (off == 0) {
        o << "every box mean within " << rubric.filterAbs << " + " << rubric.filterRel << "·|exact| (the grader's "
          << "tolerance; worst " << csvNumber(worstRatio) << "x it)\n";
        return;
    }
    const glm::vec4 b = boxes[worst];
    o << off << " off by more than " << rubric.filterAbs << " + " << rubric.filterRel << "·|exact| (" << offCentred
      << " of them centred on a texel centre, as the grader's boxes are); worst: row " << worst + 1 << " (centre "
      << csvNumber(b.x) << ", " << csvNumber(b.y) << ", size " << csvNumber(b.z) << " x " << csvNumber(b.w) << "), "
      << csvNumber(worstRatio) << "x the tolerance\n";
}

int runProbe(const ProbeArgs& a, const std::string& backend) {
    if (a.sweep && a.function != "msm") throw std::invalid_argument("--sweep is for probe msm");
    if (a.sweep) return runMsmSweep(a, backend);
    if (a.function == "gaussian") return runGaussianProbe(a, backend);
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
        printMsmVerdict(a.out.empty() ? std::cerr : std::cout, library, t, results);
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
        printSatLookupVerdict(a.out.empty() ? std::cerr : std::cout, library, boxes, results);
        return Ok;
    }
    for (const auto& m : out) results.push_back({m.x, m.y, m.z, m.w});
    writeCsv(a.out, t, {"b1", "b2", "b3", "b4"}, results);
    printMomentsVerdict(a.out.empty() ? std::cerr : std::cout, library, t, results);
    return Ok;
}

}  // namespace

void addProbeCommand(CLI::App& app, Context& ctx) {
    auto* probe = app.add_subcommand("probe", "evaluate a stage function on a CSV of inputs "
                                              "(msm, moments, sat-lookup, gaussian)");
    probe->footer(kProbeHelp);
    auto a = std::make_shared<ProbeArgs>();
    probe->add_option("function", a->function, "msm, moments, sat-lookup or gaussian")
        ->required()
        ->check(CLI::IsMember({"msm", "moments", "sat-lookup", "gaussian"}));
    probe->add_option("--solution", a->solution, "reference, student, or a folder of stage files");
    probe->add_option("--input", a->input, "input CSV (header row; columns per function, below)");
    probe->add_option("--out", a->out, "output CSV (default: stdout)");
    probe->add_option("--generate", a->generate, "write the inputs of a named case set instead");
    probe->add_option("--alpha", a->alpha, "moment bias uMomentBias (default 3e-5)");
    probe->add_option("--map", a->map, "sat-lookup: moment map (RGBA EXR)");
    probe->add_option("--map-size", a->mapSize, "sat-lookup: size of the synthetic map (default 1024)")
        ->check(CLI::Range(1, 8192));
    probe->add_option("--radius", a->radius, "gaussian: the kernel's radius r, 2r + 1 taps (default 4)")
        ->check(CLI::Range(0, 64));
    probe->add_option("--sigma", a->sigma, "gaussian: sigma of the weights (default r / 2)");
    probe->add_option("--passes", a->passes, "gaussian: x, y or xy (x then y; default)")
        ->check(CLI::IsMember({"x", "y", "xy"}));
    probe->add_option("--size", a->size, "gaussian --generate: one map size WxH (default 7x5, 67x3, 3x67, 1x1)");
    probe->add_flag("--sweep", a->sweep, "msm: the property sweep over 10^6 generated cases");
    probe->add_option("--vectors", a->vectors, "msm --sweep: moment vectors, 4 cases each (default 250000)")
        ->check(CLI::Range(1, 4000000));
    probe->add_option("--seed", a->seed, "msm --sweep: the generator's seed (default 20150225)");
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
