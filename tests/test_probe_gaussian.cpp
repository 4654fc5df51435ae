// `shadowlab probe gaussian` (a student can check their blur against the contract): the solution's
// gaussian_blur.comp on small maps whose sizes leave work groups partly outside the image, next to
// the contract's blur in double. The reference matches within float rounding at every radius and
// pass; the catalogue's Gaussian mutants and two made here (a wrong clamp, a missing weight) are
// caught; the stub is named.
#include "gaussian_cases.h"
#include "gaussian_exact.h"
#include "gl_test_support.h"
#include "renderer.h"

#include <fstream>

namespace sl {
namespace {

struct GaussianRun {
    test::CommandResult result;
    std::vector<std::vector<std::string>> rows;  // the output CSV, header first
};

GaussianRun probeGaussian(const std::string& solution, const fs::path& maps, const std::string& options) {
    const fs::path out = maps.parent_path() / "blurred.csv";
    fs::remove(out);
    GaussianRun run;
    run.result = test::runCommand(test::shadowlabBinary() + " probe gaussian --solution " + solution + " --input " +
                                  maps.string() + " " + options + " --out " + out.string());
    run.rows = test::readCsv(out);
    return run;
}

fs::path generatedMaps(const std::string& name) {
    const fs::path dir = test::tempDir(name);
    auto gen = test::runCommand(test::shadowlabBinary() + " probe gaussian --generate all --out " +
                                (dir / "maps.csv").string());
    EXPECT_EQ(gen.exitCode, 0) << gen.output;
    return dir / "maps.csv";
}

// A copy of the reference's gaussian_blur.comp with `from` replaced by `to` (exactly once).
std::string referenceMutant(const std::string& name, const std::string& from, const std::string& to) {
    std::string src = test::readFile(test::root() / "reference/gaussian_blur.comp");
    const size_t at = src.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    EXPECT_EQ(src.find(from, at + 1), std::string::npos) << from;
    if (at != std::string::npos) src.replace(at, from.size(), to);
    const fs::path dir = test::tempDir(name);
    test::writeFile(dir / "gaussian_blur.comp", src);
    return dir.string();
}

}  // namespace

TEST(ProbeGaussian, ExpectedValuesAreTheContractsWeightsInDouble) {
    for (int r : {0, 1, 4, 16, 64})
        for (double sigma : {0.0, 1.5, double(r)}) {
            const auto w = exactGaussianWeights(r, sigma);
            ASSERT_EQ(w.size(), size_t(r) + 1);
            double sum = w[0];
            for (int k = 1; k <= r; ++k) sum += 2 * w[size_t(k)];
            EXPECT_NEAR(sum, 1.0, 1e-15);
            const auto f = Renderer::gaussianWeights(r, float(sigma));  // what the shader gets
            for (int k = 0; k <= r; ++k) EXPECT_NEAR(w[size_t(k)], f[size_t(k)], 1e-7) << r << " " << k;
            if (r > 1 && sigma > 0)  // the ratio of neighbours is the Gaussian's
                EXPECT_NEAR(w[1] / w[0], std::exp(-1 / (2 * sigma * sigma)), 1e-14);
        }
    // An impulse in a row blurred along x is the kernel; along y it is left alone.
    Image m(9, 1, 4);
    m.at(4, 0, 0) = 1;
    const auto w = exactGaussianWeights(3, 0);
    const auto x = exactGaussianBlur(m, 3, 0, true, false), y = exactGaussianBlur(m, 3, 0, false, true);
    for (int i = 0; i < 9; ++i) EXPECT_DOUBLE_EQ(x[size_t(i) * 4], i >= 1 && i <= 7 ? w[size_t(std::abs(i - 4))] : 0.0);
    EXPECT_DOUBLE_EQ(y[16], 1.0);  // one row: clamp to edge repeats it, and the weights sum to 1
    // Clamp to edge: the border texel stands in for the taps past it.
    Image e(3, 1, 4);
    e.at(0, 0, 0) = 1;
    const auto w2 = exactGaussianWeights(2, 0);  // texel 0 reads texels -2, -1, 0 as texel 0
    EXPECT_NEAR(exactGaussianBlur(e, 2, 0, true, false)[0], w2[0] + w2[1] + w2[2], 1e-15);
    // The named maps: every kind at sizes that leave work groups partly outside the image.
    const auto all = gaussianCases("all");
    EXPECT_EQ(all.size(), 16u);
    bool partial = false, single = false;
    for (const auto& c : all) {
        partial = partial || c.map.width % 64 != 0;
        single = single || (c.map.width == 1 && c.map.height == 1);
    }
    EXPECT_TRUE(partial && single);
    EXPECT_THROW(gaussianCases("ramp"), std::invalid_argument);
}

TEST(ProbeGaussian, ReferenceMatchesTheDoubleBlurWithinFloatRounding) {
    const fs::path maps = generatedMaps("probe_gaussian_reference");
    for (const char* options : {"--radius 4", "--radius 1 --passes x", "--radius 16 --sigma 3 --passes y",
                                "--radius 0", "--radius 64"}) {
        SCOPED_TRACE(options);
        const auto run = probeGaussian("reference", maps, options);
        ASSERT_EQ(run.result.exitCode, 0) << run.result.output;
        EXPECT_NE(run.result.output.find("every map within float rounding"), std::string::npos) << run.result.output;
        ASSERT_EQ(run.rows.size(), 1 + 4 * (7 * 5 + 67 * 3 + 3 * 67 + 1));
        const auto& h = run.rows[0];
        ASSERT_EQ(h.back(), "max_error");
        ASSERT_EQ(h[7], "b1");
        ASSERT_EQ(h[11], "expected_b1");
        const int r = std::atoi(std::string(options).substr(9).c_str());
        const double u = std::ldexp(1.0, -24), tol = 2 * (2 * r + 3) * u;
        for (size_t i = 1; i < run.rows.size(); ++i) {
            ASSERT_EQ(run.rows[i].size(), h.size());
            EXPECT_LE(std::stod(run.rows[i].back()), tol) << i;
            for (int c = 0; c < 4; ++c)  // the columns say what max_error says
                EXPECT_LE(std::abs(std::stod(run.rows[i][7 + size_t(c)]) - std::stod(run.rows[i][11 + size_t(c)])),
                          std::stod(run.rows[i].back()) + 1e-8);  // + %.9g printing
        }
    }
}

TEST(ProbeGaussian, MutantsAreCaughtAndTheStubIsNamed) {
    const fs::path maps = generatedMaps("probe_gaussian_mutants");
    const fs::path mutants = test::root() / "tests/submissions/mutants";
    std::vector<std::pair<std::string, std::string>> cases;  // solution, options
    for (const char* m : {"gaussian_edge_mirror", "gaussian_edge_wrap", "gaussian_edge_zero",
                          "gaussian_ignores_direction", "gaussian_one_sided_kernel", "gaussian_radius_off_by_one",
                          "gaussian_unnormalised_weights"})
        cases.push_back({(mutants / m).string(), "--radius 4"});
    // Right only where sigma = r / 2.
    cases.push_back({(mutants / "gaussian_ignores_weights").string(), "--radius 4 --sigma 1.5"});
    // Made here: a clamp one texel past the image (it reads 0 there), and the outermost weight
    // missing.
    cases.push_back({referenceMutant("probe_gaussian_wrong_clamp", "clamp(first + (i - R) * uDirection, ivec2(0), last)",
                                     "clamp(first + (i - R) * uDirection, ivec2(0), last + 1)"),
                     "--radius 4"});
    cases.push_back({referenceMutant("probe_gaussian_missing_weight", "for (int k = R / 2 + 1; k <= R; ++k)",
                                     "for (int k = R / 2 + 1; k < R; ++k)"),
                     "--radius 4"});
    for (const auto& [solution, options] : cases) {
        SCOPED_TRACE(solution);
        const auto run = probeGaussian(solution, maps, options);
        ASSERT_EQ(run.result.exitCode, 0) << run.result.output;
        EXPECT_NE(run.result.output.find("maps beyond float rounding"), std::string::npos) << run.result.output;
        EXPECT_EQ(run.result.output.find("every map within"), std::string::npos) << run.result.output;
    }
    // The student's stub: named, not measured.
    const auto stub = probeGaussian("student", maps, "--radius 4");
    ASSERT_EQ(stub.result.exitCode, 0) << stub.result.output;
    EXPECT_NE(stub.result.output.find("student/gaussian_blur.comp: main (one Gaussian pass): not implemented yet"),
              std::string::npos) << stub.result.output;
    EXPECT_EQ(stub.result.output.find("beyond float rounding"), std::string::npos) << stub.result.output;
}

TEST(ProbeGaussian, InputErrorsNameTheFileAndLine) {
    const fs::path dir = test::tempDir("probe_gaussian_errors");
    const std::string bin = test::shadowlabBinary();
    auto probe = [&](const std::string& name, const std::string& csv) {
        test::writeFile(dir / name, csv);
        return test::runCommand(bin + " probe gaussian --input " + (dir / name).string());
    };
    auto r = probe("missing.csv", "x,y,m1,m2,m3,m4\n0,0,1,1,1,1\n1,1,1,1,1,1\n");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("has no row for texel (1, 0)"), std::string::npos) << r.output;
    r = probe("twice.csv", "map,x,y,m1,m2,m3,m4\na,0,0,1,1,1,1\na,0,0,1,1,1,1\n");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("twice.csv:3: map 'a' has texel (0, 0) twice (first on line 2)"), std::string::npos)
        << r.output;
    r = probe("half.csv", "x,y,m1,m2,m3,m4\n0.5,0,1,1,1,1\n");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("half.csv:2: x and y must be whole texel indices"), std::string::npos) << r.output;
    r = probe("nox.csv", "y,m1,m2,m3,m4\n0,1,1,1,1\n");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("column 'x' is missing"), std::string::npos) << r.output;
    // One map without a map column, one texel: the blur of a 1x1 map is the map (any radius).
    r = probe("one.csv", "x,y,m1,m2,m3,m4\n0,0,0.5,0.25,0.125,0.0625\n");
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("0,0,0.5,0.25,0.125,0.0625,0.5,0.25,0.125,0.0625,0.5,0.25,0.125,0.0625,"),
              std::string::npos) << r.output;
    r = test::runCommand(bin + " probe gaussian --generate impulse --size 9x2");
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("impulse-9x2,4,1,1,0.5,0.25,0.125"), std::string::npos) << r.output;
    r = test::runCommand(bin + " probe gaussian --generate impulse --size 9by2");
    EXPECT_EQ(r.exitCode, 2) << r.output;
}

}  // namespace sl
