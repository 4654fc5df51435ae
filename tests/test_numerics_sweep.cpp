// Properties of momentShadowIntensity over 10⁶ generated cases (docs/numerics.md, "Sweep"):
// 250 000 moment vectors of random depth distributions (mixtures of point masses and
// uniform intervals in [0, 1], a quarter of them perturbed adversarially), each at 4 sorted
// fragment depths (msm_sweep.h). Checked for the reference on the GPU (one probe dispatch) and
// for its float32 CPU mirror: G finite and in [0, 1]; monotone in zf; ~0 in front of every
// occluder; within a stated bound of the exact 4MSM value; GPU and mirror agree. And the
// solver-free checks of `shadowlab probe msm --sweep` (any solution, the student kit too):
// the reference and the correct variants pass them, the mutants fail them, a stub is named.
#include "gl_test_support.h"
#include "msm_exact.h"
#include "msm_robustness.h"
#include "msm_sweep.h"
#include "oracles/msm_float_mirror.h"
#include "probe.h"
#include "probe_cases.h"

#include <chrono>
#include <cmath>
#include <random>

namespace sl {
namespace {

constexpr float kSweepAlpha = kReferenceMomentBias;
// Stated bounds for the reference (docs/numerics.md; the solver-free ones: msm_sweep.h).
// Monotone: the reference's G drops by at most this much (the robustness stage allows 1e-3).
constexpr double kReferenceMonotoneSlack = 1e-4;
// Versus the exact value: kExactBase + 4·(float sensitivity of the case) (msm_exact.h).
constexpr double kExactBase = 2e-4;

double seconds(std::chrono::steady_clock::time_point since) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

}  // namespace

TEST(NumericsSweep, MillionCasesOnGpuAndCpuMirror) {
    const auto start = std::chrono::steady_clock::now();
    const MsmSweepCases c = generateMsmSweep();
    const size_t n = c.b.size();
    ASSERT_GE(n, 1000000u);
    const double tGenerate = seconds(start);

    test::sharedContext();
    auto t0 = std::chrono::steady_clock::now();
    const std::vector<float> gpu = probeMomentShadowIntensity(test::library("reference"), c.b, c.zf, kSweepAlpha);
    const double tGpu = seconds(t0);

    t0 = std::chrono::steady_clock::now();
    size_t bad[2] = {0, 0}, nonMonotone[2] = {0, 0}, frontLeak[2] = {0, 0}, offExact[2] = {0, 0};
    size_t disagree = 0, exactChecked = 0;
    double worstExact[2] = {0, 0}, worstDisagree = 0, worstInvalid = 0;
    std::string firstProblem;  // up to 12 problems, with their inputs
    int problems = 0;
    auto note = [&](const std::string& what, size_t i, float g) {
        if (problems++ >= 12) return;
        char buf[320];
        std::snprintf(buf, sizeof buf, "\n  %s: b = (%.9g, %.9g, %.9g, %.9g), zf = %.9g, G = %.9g (exact %.9g, sens %.3g)",
                      what.c_str(), c.b[i].x, c.b[i].y, c.b[i].z, c.b[i].w, c.zf[i], g,
                      exactMomentShadowIntensity(glm::dvec4(c.b[i]), c.zf[i], kSweepAlpha),
                      msmFloatSensitivity(c.b[i], c.zf[i], kSweepAlpha));
        firstProblem += buf;
    };
    std::vector<float> cpu(n);
    for (size_t i = 0; i < n; ++i) cpu[i] = mirror::momentShadowIntensity(c.b[i], c.zf[i], kSweepAlpha);
    for (size_t i = 0; i < n; ++i) {
        const size_t v = i / kMsmSweepDepthsPerVector;
        const double exact = exactMomentShadowIntensity(glm::dvec4(c.b[i]), c.zf[i], kSweepAlpha);
        exactChecked += std::isfinite(exact);
        double sensitivity = -1;  // computed only where needed (18 exact solves)
        auto bound = [&] {
            if (sensitivity < 0) sensitivity = msmFloatSensitivity(c.b[i], c.zf[i], kSweepAlpha);
            return kExactBase + 4 * sensitivity;
        };
        for (int side = 0; side < 2; ++side) {
            const float g = side == 0 ? gpu[i] : cpu[i];
            const char* who = side == 0 ? "GPU" : "CPU mirror";
            if (!(std::isfinite(g) && g >= 0.0f && g <= 1.0f)) ++bad[side], note(std::string(who) + " not in [0,1]", i, g);
            if (i % kMsmSweepDepthsPerVector && g < (side == 0 ? gpu[i - 1] : cpu[i - 1]) - kReferenceMonotoneSlack)
                ++nonMonotone[side], note(std::string(who) + " non-monotone", i, g);
            if (c.zf[i] <= c.minDepth[v] - kSweepFrontMargin && !c.perturbed[v] && g > kSweepFrontMax)
                ++frontLeak[side], note(std::string(who) + " G > 0 in front of every occluder", i, g);
            if (std::isfinite(exact)) {
                const double err = std::abs(g - exact);
                if (err > kExactBase && err > bound()) ++offExact[side], note(std::string(who) + " off exact", i, g);
                if (err <= kExactBase || sensitivity < 1e-3) worstExact[side] = std::max(worstExact[side], err);
            }
        }
        // Agreement is required where b is a valid moment vector; outside the moment space
        // (adversarial perturbations) the result is chaotic, and only range and
        // monotonicity are asked of it.
        const double d = std::abs(double(gpu[i]) - cpu[i]);
        if (!std::isfinite(exact)) {
            worstInvalid = std::max(worstInvalid, d);
            continue;
        }
        if (d > kExactBase && d > bound()) ++disagree, note("GPU vs CPU mirror", i, gpu[i]);
        if (d <= kExactBase || sensitivity < 1e-3) worstDisagree = std::max(worstDisagree, d);
    }
    const double tCheck = seconds(t0);
    if (problems) std::printf("problems:%s\n", firstProblem.c_str());
    std::printf("sweep: %zu cases (%zu with an exact value); generate %.2f s, GPU %.2f s, CPU checks %.2f s\n",
                n, exactChecked, tGenerate, tGpu, tCheck);
    for (int side = 0; side < 2; ++side)
        std::printf("  %-10s: not in [0,1] %zu, non-monotone %zu, leak in front %zu, off exact %zu; "
                    "max |G - exact| where well-conditioned %.3g\n",
                    side == 0 ? "GPU" : "CPU mirror", bad[side], nonMonotone[side], frontLeak[side],
                    offExact[side], worstExact[side]);
    std::printf("  GPU vs mirror: %zu disagree; max |GPU - mirror| where well-conditioned %.3g, "
                "on invalid moment vectors %.3g\n", disagree, worstDisagree, worstInvalid);
    for (int side = 0; side < 2; ++side) {
        EXPECT_EQ(bad[side], 0u) << firstProblem;
        EXPECT_EQ(nonMonotone[side], 0u) << firstProblem;
        EXPECT_EQ(frontLeak[side], 0u) << firstProblem;
        EXPECT_EQ(offExact[side], 0u) << firstProblem;
    }
    EXPECT_EQ(disagree, 0u) << firstProblem;
    EXPECT_GT(exactChecked, n / 2);
    EXPECT_LT(seconds(start), 60.0);
}

}  // namespace sl

namespace sl {
namespace {

std::string sweepSubmission(const std::string& rel) { return (test::root() / "tests/submissions" / rel).string(); }

}  // namespace

// The checks `probe msm --sweep` makes without a solver, on the same 10⁶ cases: every correct
// solve passes them (the reference, and the msm alternatives the grader gives full marks), every
// msm mutant and the unguarded variant fails them, and a stub is told apart.
TEST(NumericsSweep, SolverFreeChecksPassCorrectSolutionsAndCatchMutants) {
    test::sharedContext();
    const MsmSweepCases c = generateMsmSweep();
    auto sweep = [&](const std::string& solution) {
        const auto g = probeMomentShadowIntensity(test::library(solution), c.b, c.zf, kSweepAlpha);
        const MsmSweepReport r = checkMsmSweep(c, g, kSweepAlpha);
        std::printf("%s:\n%s", solution.c_str(), msmSweepSummary(r, c, g, kSweepAlpha, 2).c_str());
        return r;
    };
    const MsmSweepReport ref = sweep("reference");
    EXPECT_EQ(ref.failures(), 0u);
    EXPECT_LE(ref.worstDrop, kReferenceMonotoneSlack);  // docs/numerics.md quotes 1e-4
    EXPECT_GT(ref.checkedCantelli, c.b.size() / 2);
    EXPECT_GT(ref.checkedFront, c.b.size() / 5);
    EXPECT_FALSE(ref.stub);
    for (const char* alt : {"msm_cholesky_sqrt", "msm_float64", "msm_pivot_floor_1e-11", "msm_pivot_floor_1e-8",
                            "msm_textbook_quadratic"})
        EXPECT_EQ(sweep(sweepSubmission(std::string("alternatives/") + alt)).failures(), 0u) << alt;
    for (const char* mutant : {"mutants/msm_bias_mix_reversed", "mutants/msm_case_formulas_mixed",
                               "mutants/msm_forward_substitution_sign", "mutants/msm_g_inverted",
                               "mutants/msm_no_moment_bias", "mutants/msm_roots_swapped",
                               "mutants/msm_weights_moment_index_shift", "fragile/unguarded"})
        EXPECT_GT(sweep(sweepSubmission(mutant)).failures(), 0u) << mutant;
    // The no-bias mutant is the subtle one: G > 1e-4 in front of every occluder.
    EXPECT_GT(sweep(sweepSubmission("mutants/msm_no_moment_bias")).frontLeak, 0u);
    const MsmSweepReport stub = sweep("student");
    EXPECT_TRUE(stub.stub);
    EXPECT_EQ(stub.failures(), 0u);
}

// The two-moment bounds the sweep checks hold the exact 4MSM value (it is the smallest weight
// in front of zf over the distributions with all four moments, so it lies between them).
TEST(NumericsSweep, CantelliBoundsHoldTheExactValue) {
    const MsmSweepCases c = generateMsmSweep(2000, 7);
    size_t checked = 0, tight = 0;
    for (size_t i = 0; i < c.b.size(); ++i) {
        if (c.perturbed[i / kMsmSweepDepthsPerVector]) continue;
        for (float zf : {c.zf[i], c.zf[i] + 0.1f, c.zf[i] - 0.1f}) {
            const double exact = exactMomentShadowIntensity(glm::dvec4(c.b[i]), zf, kSweepAlpha);
            if (!std::isfinite(exact)) continue;
            const CantelliBounds cb = msmCantelliBounds(c.b[i], zf, kSweepAlpha);
            ++checked;
            ASSERT_GE(exact, cb.lower - 1e-9) << i << " zf " << zf;
            ASSERT_LE(exact, cb.upper + 1e-9) << i << " zf " << zf;
            tight += cb.lower > 0.5 || cb.upper < 0.5;  // the bounds decide something
        }
    }
    EXPECT_GT(checked, 4000u);
    EXPECT_GT(tight, checked / 5);
    // By hand: depth 0.5 only, alpha 0: mean 0.5, variance 0; zf = 0.6 → lower bound 1.
    EXPECT_NEAR(msmCantelliBounds({0.5f, 0.25f, 0.125f, 0.0625f}, 0.6f, 0.0f).lower, 1.0, 1e-6);
    EXPECT_NEAR(msmCantelliBounds({0.5f, 0.25f, 0.125f, 0.0625f}, 0.4f, 0.0f).upper, 0.0, 1e-6);
}

// The command: a summary that says what it checks, the failing cases to a file that `probe msm
// --input` takes back, and a stub named as not implemented.
TEST(NumericsSweep, ProbeMsmSweepCommandSummarisesAnySolution) {
    const std::string bin = test::shadowlabBinary();
    const fs::path dir = test::tempDir("probe_msm_sweep");
    auto r = test::runCommand(bin + " probe msm --sweep --solution reference");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (const char* s : {"1000000 cases", "need no 4MSM solver", "G finite, in [0, 1]", "monotone in zf",
                          "in front of every occluder", "Cantelli", "no failures"})
        EXPECT_NE(r.output.find(s), std::string::npos) << s << "\n" << r.output;
    r = test::runCommand(bin + " probe msm --sweep --solution student");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("student/msm.glsl: momentShadowIntensity: not implemented yet"), std::string::npos)
        << r.output;
    const std::string mutant = sweepSubmission("mutants/msm_roots_swapped");
    const fs::path fails = dir / "fails.csv", again = dir / "again.csv";
    r = test::runCommand(bin + " probe msm --sweep --vectors 20000 --seed 3 --solution " + mutant + " --out " +
                         fails.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("80000 cases"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("failures; the first 12"), std::string::npos) << r.output;
    r = test::runCommand(bin + " probe msm --solution " + mutant + " --input " + fails.string() + " --out " +
                         again.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    // Probing the failing rows gives the same G: the column G of the sweep's file, then the probe's.
    std::istringstream in(test::readFile(again));
    std::string line;
    size_t rows = 0;
    std::getline(in, line);
    EXPECT_EQ(line, "check,m1,m2,m3,m4,zf,G,bound,G");
    while (std::getline(in, line)) {
        const size_t last = line.rfind(','), before = line.rfind(',', line.rfind(',', last - 1) - 1);
        const std::string swept = line.substr(before + 1, line.find(',', before + 1) - before - 1);
        EXPECT_EQ(std::stof(swept), std::stof(line.substr(last + 1))) << line;
        ++rows;
    }
    EXPECT_GT(rows, 100u);
    r = test::runCommand(bin + " probe moments --sweep --solution reference");
    EXPECT_EQ(r.exitCode, 2) << r.output;
}

}  // namespace sl
