// The hard-case catalogue (framework/numerics/probe_cases.h, docs/numerics.md): its expected values
// against the analytic CDF of point masses, the reference on the GPU (through the grader's
// robustness stage) and its float32 CPU mirror, and `shadowlab probe` on its CSV files.
#include "gl_test_support.h"
#include "msm_robustness.h"
#include "oracles/moment_oracles.h"
#include "oracles/msm_float_mirror.h"
#include "probe_cases.h"

#include <cmath>
#include <fstream>
#include <map>

namespace sl {
namespace {

constexpr double kAlpha = double(kReferenceMomentBias);

}  // namespace

TEST(NumericsCatalogue, EverySetIsNonEmptyAndNamed) {
    size_t total = 0;
    for (const auto& name : msmCaseSetNames()) {
        auto set = msmCaseSet(name);
        EXPECT_GE(set.size(), 10u) << name;
        for (const auto& c : set) EXPECT_EQ(c.set, name);
        total += set.size();
    }
    EXPECT_EQ(msmHardCaseCatalogue().size(), total);
    EXPECT_THROW(msmCaseSet("no-such-set"), std::invalid_argument);
}

TEST(NumericsCatalogue, ExactSolverMatchesTheAnalyticCdfOfPointMasses) {
    // Where the moments determine the distribution (Hankel matrix singular: at most two
    // support points), 4MSM returns its CDF strictly below zf. With α = 0: one depth z
    // (rank 1) gives [zf > z]; two depths (rank 2) give w1·[zf > z1] + w2·[zf > z2].
    for (double z : {0.0, 0.1, 0.5, 0.731, 1.0})
        for (double zf : {-0.5, 0.0, 0.5 * z, z - 1e-3, z + 1e-3, 0.5 * (z + 1), 1.0, 1.5})
            EXPECT_EQ(exactMomentShadowIntensity(oracle::computeMoments(z), zf, 0.0), zf > z ? 1.0 : 0.0)
                << z << " " << zf;
    for (auto [z1, z2, w] : {std::tuple{0.2, 0.8, 0.5}, {0.3, 0.31, 0.25}, {0.0, 0.6, 0.9}})
        for (double zf : {0.1, 0.5 * (z1 + z2), 0.9}) {
            const glm::dvec4 b = w * oracle::computeMoments(z1) + (1 - w) * oracle::computeMoments(z2);
            EXPECT_NEAR(exactMomentShadowIntensity(b, zf, 0.0), w * (zf > z1) + (1 - w) * (zf > z2), 1e-9)
                << z1 << "," << z2 << " " << zf;
        }
    // With the bias, depth only at 0 and 1 (weight w at 1) stays rank 2: the bias vector is
    // itself that distribution. G = w0'·[zf > 0] + w1'·[zf > 1], w1' = (1 − α)·w + α/2.
    const double a = kAlpha;
    for (double w : {0.0, 0.3, 1.0})
        for (double zf : {-0.1, 0.0, 0.4, 1.0, 1.2}) {
            const double w1 = (1 - a) * w + a / 2;
            const double want = (1 - w1) * (zf > 0) + w1 * (zf > 1);
            EXPECT_NEAR(exactMomentShadowIntensity(glm::dvec4(w), zf, a), want, 1e-12) << w << " " << zf;
        }
    // With the bias every other case is regular: there the long-double adjugate solver and the
    // double LDLᵀ oracle (tests/oracles), two independent routes, agree.
    int compared = 0;
    for (const auto& c : msmHardCaseCatalogue()) {
        if (c.set == "depth-0-1" || c.set == "denormals" || !std::isfinite(c.expected)) continue;
        const double d = oracle::msm4Hamburger(glm::dvec4(c.b), c.zf, kAlpha);
        if (msmFloatSensitivity(c.b, c.zf, kAlpha) > 1e-3) continue;  // at a jump of G
        EXPECT_NEAR(c.expected, d, 1e-6) << c.name;
        ++compared;
    }
    EXPECT_GT(compared, 120);
}

TEST(NumericsCatalogue, ReferenceOnTheGpuPassesEveryCase) {
    test::sharedContext();
    RobustnessReport r = probeMsmRobustness(test::library("reference"));
    std::printf("%s", r.summary(50).c_str());
    EXPECT_EQ(r.failed, 0) << r.summary(50);
    EXPECT_EQ(r.score, 1.0);
    // The figures of docs/numerics.md: per set, the largest error and its share of the bound.
    // "Ill-conditioned": bound >= 0.5, i.e. float32 rounding of the inputs alone can move the
    // exact G across most of [0, 1]; there only finiteness, range and monotonicity count.
    struct Row { int cases = 0, withExpected = 0, ill = 0; double worst = 0, worstShare = 0, worstIll = 0; };
    std::map<std::string, Row> rows;
    for (const auto& c : r.cases) {
        Row& row = rows[c.input.set];
        ++row.cases;
        if (!std::isfinite(c.input.expected)) continue;
        ++row.withExpected;
        const double err = std::abs(c.G - c.input.expected);
        if (c.input.bound >= 0.5) {
            ++row.ill;
            row.worstIll = std::max(row.worstIll, err);
            continue;
        }
        row.worst = std::max(row.worst, err);
        row.worstShare = std::max(row.worstShare, err / c.input.bound);
    }
    std::printf("| set | cases | with expected | of those ill-conditioned | max abs(G - expected), "
                "well-conditioned | max error / bound | max abs(G - expected), ill-conditioned |\n");
    for (const auto& name : msmCaseSetNames()) {
        const Row& row = rows[name];
        std::printf("| %s | %d | %d | %d | %.2g | %.3f | %.2g |\n", name.c_str(), row.cases, row.withExpected,
                    row.ill, row.worst, row.worstShare, row.worstIll);
    }
}

TEST(NumericsCatalogue, CpuMirrorPassesEveryCase) {
    for (const auto& c : msmHardCaseCatalogue()) {
        const float g = mirror::momentShadowIntensity(c.b, c.zf, kReferenceMomentBias);
        ASSERT_TRUE(std::isfinite(g) && g >= 0.0f && g <= 1.0f) << c.name << " G=" << g;
        if (std::isfinite(c.expected)) EXPECT_NEAR(g, c.expected, c.bound) << c.name;
    }
}

TEST(NumericsCatalogue, ProbeCommandRunsTheGeneratedCatalogue) {
    const fs::path dir = test::tempDir("probe_catalogue");
    const std::string bin = test::shadowlabBinary();
    auto gen = test::runCommand(bin + " probe msm --generate catalogue --out " + (dir / "cases.csv").string());
    ASSERT_EQ(gen.exitCode, 0) << gen.output;
    auto run = test::runCommand(bin + " probe msm --input " + (dir / "cases.csv").string() + " --out " +
                                (dir / "results.csv").string());
    ASSERT_EQ(run.exitCode, 0) << run.output;
    std::ifstream in(dir / "results.csv");
    std::string header, line;
    std::getline(in, header);
    EXPECT_EQ(header, "case,m1,m2,m3,m4,zf,expected,bound,note,G");
    size_t rows = 0;
    while (std::getline(in, line)) {
        ++rows;
        const double g = std::stod(line.substr(line.rfind(',') + 1));
        EXPECT_TRUE(g >= 0.0 && g <= 1.0) << line;
    }
    EXPECT_EQ(rows, msmHardCaseCatalogue().size());
    auto help = test::runCommand(bin + " probe --help");
    EXPECT_NE(help.output.find("3e-5"), std::string::npos) << help.output;
    EXPECT_NE(help.output.find("(0.5, 0.5, 0.5, 0.5)"), std::string::npos) << help.output;
    EXPECT_NE(help.output.find("lightDepth,near,far"), std::string::npos) << help.output;
    EXPECT_NE(help.output.find("cx,cy,w,h"), std::string::npos) << help.output;
}

TEST(NumericsCatalogue, ProbeCommandNamesFileLineAndColumnOfBadCsv) {
    const fs::path dir = test::tempDir("probe_bad_csv");
    std::ofstream(dir / "bad.csv") << "name,m1,m2,m3,m4,zf\nok,0.5,0.25,0.125,0.0625,0.7\n"
                                      "broken,0.5,0.25,oops,0.0625,0.7\n";
    auto r = test::runCommand(test::shadowlabBinary() + " probe msm --input " +
                              (dir / "bad.csv").string() + " --out " + (dir / "out.csv").string());
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("bad.csv:3"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("'m3'"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("'oops'"), std::string::npos) << r.output;
    std::ofstream(dir / "missing.csv") << "m1,m2,m3,m4\n0.5,0.25,0.125,0.0625\n";
    r = test::runCommand(test::shadowlabBinary() + " probe msm --input " + (dir / "missing.csv").string());
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("missing.csv:1: column 'zf' is missing"), std::string::npos) << r.output;
}

TEST(NumericsCatalogue, ProbeCommandPassesExtraColumnsThroughAndProbesTheOtherFunctions) {
    const fs::path dir = test::tempDir("probe_other");
    const std::string bin = test::shadowlabBinary();
    std::ofstream(dir / "m.csv") << "label,lightDepth,near,far\na,5,1,9\n";
    auto r = test::runCommand(bin + " probe moments --input " + (dir / "m.csv").string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("label,lightDepth,near,far,b1,b2,b3,b4"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("a,5,1,9,0.5,0.25,0.125,0.0625"), std::string::npos) << r.output;
    std::ofstream(dir / "s.csv") << "cx,cy,w,h\n0.5,0.5,1,1\n";
    r = test::runCommand(bin + " probe sat-lookup --map-size 64 --input " + (dir / "s.csv").string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("0.5,0.5,1,1,0.6"), std::string::npos) << r.output;
}

}  // namespace sl
