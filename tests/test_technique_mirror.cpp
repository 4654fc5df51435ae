// Each technique's GLSL against a double-precision CPU mirror (GLM), on probe inputs: moments of
// random 1–3-point depth distributions, receivers in front of, between and behind them.
// shaders/techniques/probe_technique.comp runs the same functions the lighting pass compiles.
#include "gl_program.h"
#include "gl_test_support.h"
#include "gpu_resources.h"
#include "technique.h"

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>

namespace sl {
namespace {

using glm::dvec2;
using glm::dvec4;

struct ProbeInput {
    glm::vec4 a, b, c;
};

// msm.glsl's α in the probe: large enough that float tracks double (conditions B).
constexpr float kProbeMomentBias = 1e-3f;

// Runs probe function `fn` on every case; returns outputs[i].
std::vector<glm::vec4> probe(int fn, const std::vector<ProbeInput>& cases) {
    test::sharedContext();
    GlProgram p = GlProgram::compute(test::library("reference"), "techniques/probe_technique.comp", {});
    BufferHandle in = createBuffer(cases.data(), GLsizeiptr(cases.size() * sizeof(ProbeInput)));
    BufferHandle out = createBuffer(nullptr, GLsizeiptr(cases.size() * 16));
    gl::BindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, in.id());
    gl::BindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, out.id());
    p.use();
    p.set("uMomentBias", kProbeMomentBias);
    p.set("uCount", int(cases.size()));
    p.set("uFunction", fn);
    gl::DispatchCompute(GLuint((cases.size() + 63) / 64), 1, 1);
    gl::MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<glm::vec4> r(cases.size());
    gl::GetNamedBufferSubData(out.id(), 0, GLsizeiptr(r.size() * 16), r.data());
    return r;
}

// A random distribution of 1–3 depths; its power moments E[z^k] and those of a warp.
struct Distribution {
    std::vector<double> z, w;
    double moment(const std::function<double(double)>& f) const {
        double s = 0;
        for (size_t i = 0; i < z.size(); ++i) s += w[i] * f(z[i]);
        return s;
    }
    dvec4 powers() const {
        return {moment([](double x) { return x; }), moment([](double x) { return x * x; }),
                moment([](double x) { return x * x * x; }), moment([](double x) { return x * x * x * x; })};
    }
};

std::vector<Distribution> distributions(int n) {
    std::mt19937 rng(8);
    std::uniform_real_distribution<double> u(0.05, 0.95);
    std::vector<Distribution> out;
    for (int i = 0; i < n; ++i) {
        Distribution d;
        const int k = 1 + i % 3;
        double sum = 0;
        for (int j = 0; j < k; ++j) {
            d.z.push_back(u(rng));
            d.w.push_back(0.2 + u(rng));
            sum += d.w.back();
        }
        for (double& w : d.w) w /= sum;
        out.push_back(d);
    }
    return out;
}

double receiver(int i) { return std::fmod(0.013 + i * 0.6180339887, 1.0); }  // spread over [0, 1)

// --- CPU mirrors, double precision (the formulas of the files' header comments) ---
double chebyshev(dvec2 m, double t, double minVariance) {
    const double var = std::max(m.y - m.x * m.x, minVariance);
    return t <= m.x ? 1.0 : var / (var + (t - m.x) * (t - m.x));
}
double reduce(double p, double amount) { return std::clamp((p - amount) / (1 - amount), 0.0, 1.0); }

dvec2 msmRoots(dvec4 b, double zf) {
    const double D22 = std::max(b.y - b.x * b.x, 1e-10);
    const double L32 = (b.z - b.x * b.y) / D22;
    const double D33 = std::max(b.w - b.y * b.y - L32 * L32 * D22, 1e-10);
    const double y2 = zf - b.x, y3 = zf * zf - b.y - L32 * y2;
    glm::dvec3 c;
    c.z = y3 / D33;
    c.y = y2 / D22 - L32 * c.z;
    c.x = 1 - b.x * c.y - b.y * c.z;
    const double disc = std::sqrt(std::max(c.y * c.y - 4 * c.x * c.z, 0.0));
    const double r1 = (-c.y - disc) / (2 * c.z), r2 = (-c.y + disc) / (2 * c.z);
    return {std::min(r1, r2), std::max(r1, r2)};
}
double hamburgerFromRoots(dvec4 b, double zf, dvec2 z) {
    double G = 0;
    if (z.y < zf) G = 1 - (z.x * z.y - b.x * (z.x + z.y) + b.y) / ((zf - z.x) * (zf - z.y));
    else if (z.x < zf) G = (zf * z.y - b.x * (zf + z.y) + b.y) / ((z.y - z.x) * (zf - z.x));
    return std::clamp(G, 0.0, 1.0);
}
double hamburger(dvec4 b, double zf, double alpha, dvec4 bias) {
    b = (1 - alpha) * b + alpha * bias;
    return hamburgerFromRoots(b, zf, msmRoots(b, zf));
}
double hausdorff(dvec4 b, double zf, double alpha) {
    b = (1 - alpha) * b + alpha * dvec4(0.5);
    const dvec2 z = msmRoots(b, zf);
    if (z.x >= 0 && z.y <= 1) return hamburgerFromRoots(b, zf, z);
    const double den = -b.z + (1 + zf) * b.y - zf * b.x;
    const double x = std::clamp((-b.w + (1 + zf) * b.z - zf * b.y) / den, 0.0, 1.0);
    const double w0 = (b.z - (zf + x + 1) * b.y + (zf * x + zf + x) * b.x - zf * x) / (-zf * x);
    const double wx = (b.z - (zf + 1) * b.y + zf * b.x) / (x * (x - zf) * (x - 1));
    return std::clamp(w0 + (x < zf ? wx : 0.0), 0.0, 1.0);
}
dvec2 blockers(dvec4 b, double zf, double alpha) {
    b = (1 - alpha) * b + alpha * dvec4(0.5);
    const dvec2 z = msmRoots(b, zf);
    const double x0 = zf, x1 = z.x, x2 = z.y;
    const double w1 = (b.y - b.x * (x0 + x2) + x0 * x2) / ((x1 - x0) * (x1 - x2));
    const double w2 = (b.y - b.x * (x0 + x1) + x0 * x1) / ((x2 - x0) * (x2 - x1));
    double f = 0, d = 0;
    if (x1 < zf) { f += w1; d += w1 * x1; }
    if (x2 < zf) { f += w2; d += w2 * x2; }
    if (!(f > 1e-4)) return {0, zf};
    return {std::clamp(f, 0.0, 1.0), std::clamp(d / f, 0.0, zf)};
}

glm::vec4 f4(dvec4 v) { return glm::vec4(v); }
dvec4 d4(glm::vec4 v) { return dvec4(v); }

// Max |gpu − cpu| over the cases, skipping those where `skip` says the CPU value sits on a
// discontinuity (a step the float and double sides may take differently).
template <typename Cpu>
void expectMirror(int fn, const std::vector<ProbeInput>& cases, Cpu cpu, double tolerance,
                  const char* what) {
    const auto gpu = probe(fn, cases);
    double worst = 0;
    size_t worstAt = 0;
    for (size_t i = 0; i < cases.size(); ++i) {
        const double e = std::abs(double(gpu[i].x) - cpu(cases[i]));
        if (!(e <= worst)) { worst = e; worstAt = i; }
    }
    EXPECT_LE(worst, tolerance) << what << ": case " << worstAt << " gpu " << gpu[worstAt].x
                                << " cpu " << cpu(cases[worstAt]);
}

}  // namespace

TEST(TechniqueMirror, HardAndSecondDepthCompare) {
    std::vector<ProbeInput> cases;
    for (int i = 0; i < 500; ++i) {
        const float zmap = float(receiver(i)), zf = float(receiver(i + 7)), bias = float(i % 5) * 1e-3f;
        if (std::abs(zf - bias - zmap) < 1e-5f) continue;
        cases.push_back({{zmap, std::min(1.0f, zmap + 0.1f * float(i % 4)), 0, 0}, {zf, bias, 0, 0}, {}});
    }
    expectMirror(0, cases, [](const ProbeInput& c) { return c.b.x - c.b.y > c.a.x ? 1.0 : 0.0; }, 0, "hard");
    std::erase_if(cases, [](const ProbeInput& c) { return std::abs(c.b.x - 0.5f * (c.a.x + c.a.y)) < 1e-5f; });
    expectMirror(1, cases, [](const ProbeInput& c) { return c.b.x > 0.5 * (c.a.x + c.a.y) ? 1.0 : 0.0; }, 0,
                 "second-depth");
}

TEST(TechniqueMirror, VsmAndEvsm) {
    std::vector<ProbeInput> vsm, evsm2, evsm4;
    const auto ds = distributions(600);
    for (size_t i = 0; i < ds.size(); ++i) {
        const double zf = receiver(int(i));
        const double cp = i % 2 ? 5.0 : 20.0, cn = 3.0;
        const double minVar = 1e-5, bleed = i % 3 == 0 ? 0.18 : 0.0;
        const dvec4 p = ds[i].powers();
        vsm.push_back({{float(p.x), float(p.y), 0, 0}, {float(zf), float(minVar), float(bleed), 0}, {}});
        auto wp = [&](double x) { return std::exp(cp * (2 * x - 1)); };
        auto wn = [&](double x) { return -std::exp(-cn * (2 * x - 1)); };
        const glm::vec4 m(float(ds[i].moment(wp)), float(ds[i].moment([&](double x) { return wp(x) * wp(x); })),
                          float(ds[i].moment(wn)), float(ds[i].moment([&](double x) { return wn(x) * wn(x); })));
        evsm2.push_back({m, {float(zf), float(cp), float(1e-4), float(bleed)}, {}});
        evsm4.push_back({m, {float(zf), float(cp), float(cn), 0}, {1e-4f, float(bleed), 0, 0}});
    }
    expectMirror(2, vsm, [](const ProbeInput& c) {
        return 1 - reduce(chebyshev(dvec2(c.a), c.b.x, c.b.y), c.b.z);
    }, 2e-3, "vsm");
    auto evsmLit = [](dvec2 m, double zf, double c, double minVar) {
        const double w = std::exp(c * (2 * zf - 1));
        return chebyshev(m, w, minVar * (c * w) * (c * w));
    };
    expectMirror(3, evsm2, [&](const ProbeInput& c) {
        return 1 - reduce(evsmLit(dvec2(c.a), c.b.x, c.b.y, c.b.z), c.b.w);
    }, 2e-3, "evsm2");
    expectMirror(4, evsm4, [&](const ProbeInput& c) {
        const double pPos = evsmLit(dvec2(c.a), c.b.x, c.b.y, c.c.x);
        const double wn = -std::exp(-double(c.b.z) * (2 * c.b.x - 1)), s = c.b.z * wn;
        const double pNeg = chebyshev(dvec2(c.a.z, c.a.w), wn, c.c.x * s * s);
        return 1 - reduce(std::min(pPos, pNeg), c.c.y);
    }, 2e-3, "evsm4");
}

TEST(TechniqueMirror, ConvolutionShadowMaps) {
    std::vector<ProbeInput> cases;
    const auto ds = distributions(400);
    const int M = 4;  // the probe's SL_PARAM_terms default
    for (size_t i = 0; i < ds.size(); ++i) {
        glm::vec4 l[2];
        for (int k = 1; k <= M; ++k) {
            const double c = M_PI * (2 * k - 1);
            l[(k - 1) / 2][(k - 1) % 2 * 2] = float(ds[i].moment([&](double x) { return std::cos(c * x); }));
            l[(k - 1) / 2][(k - 1) % 2 * 2 + 1] = float(ds[i].moment([&](double x) { return std::sin(c * x); }));
        }
        cases.push_back({l[0], {float(receiver(int(i))), float(i % 2), 0.02f, 2.0f}, l[1]});
    }
    expectMirror(5, cases, [&](const ProbeInput& cs) {
        const glm::vec4 l[2] = {cs.a, cs.c};
        const double d = cs.b.x - cs.b.z;
        double v = 0.5;
        for (int k = 1; k <= M; ++k) {
            const double c = M_PI * (2 * k - 1);
            const double ec = l[(k - 1) / 2][(k - 1) % 2 * 2], es = l[(k - 1) / 2][(k - 1) % 2 * 2 + 1];
            v += std::exp(-cs.b.y * double(k * k) / (M * M)) * (2 / c) * (es * std::cos(c * d) - ec * std::sin(c * d));
        }
        return 1 - std::clamp(cs.b.w * (v - 0.5) + 0.5, 0.0, 1.0);
    }, 1e-4, "csm");
}

TEST(TechniqueMirror, MomentVariants) {
    std::vector<ProbeInput> plain, quantised;
    const auto ds = distributions(600);
    const double alpha = kProbeMomentBias;  // the variants' own α, and msm.glsl's
    for (size_t i = 0; i < ds.size(); ++i) {
        const dvec4 b = ds[i].powers();
        const float zf = float(receiver(int(i)));
        plain.push_back({f4(b), {zf, float(alpha), 0, 0}, {}});
        quantised.push_back({f4(quantizeMoments16(b)), {zf, float(alpha), 0, 0}, {}});
    }
    expectMirror(10, plain, [&](const ProbeInput& c) { return hamburger(d4(c.a), c.b.x, c.b.y, dvec4(0.5)); },
                 5e-3, "hamburger");
    expectMirror(6, plain, [&](const ProbeInput& c) { return hausdorff(d4(c.a), c.b.x, c.b.y); }, 5e-3,
                 "msm4-hausdorff");
    // 16-bit: α toward (½, ⅓, ¼, ⅕), then msm.glsl's own α toward (½, ½, ½, ½).
    expectMirror(7, quantised, [&](const ProbeInput& c) {
        const dvec4 b = glm::mix(dequantizeMoments16(d4(c.a)), dvec4(0.5, 1.0 / 3, 0.25, 0.2), double(c.b.y));
        return hamburger(b, c.b.x, alpha, dvec4(0.5));
    }, 5e-3, "msm4-16bit");
    // Blockers: fraction and mean depth.
    const auto gpu = probe(8, plain);
    for (size_t i = 0; i < plain.size(); ++i) {
        const dvec2 cpu = blockers(d4(plain[i].a), plain[i].b.x, alpha);
        EXPECT_NEAR(gpu[i].x, cpu.x, 5e-3) << "blocker fraction, case " << i;
        EXPECT_NEAR(gpu[i].y, cpu.y, 5e-3) << "blocker depth, case " << i;
    }
    // The GLSL transform is the CPU one (the matrices' layout in GLSL is column-major).
    const auto q = probe(9, plain);
    for (size_t i = 0; i < plain.size(); ++i) {
        const dvec4 cpu = quantizeMoments16(d4(plain[i].a));
        for (int c = 0; c < 4; ++c) EXPECT_NEAR(q[i][c], cpu[c], 1e-5) << i;
    }
}

TEST(TechniqueMirror, HausdorffIsAtLeastHamburgerAndAtMostTheTruth) {
    // The Hausdorff bound knows depths lie in [0, 1], so it is sharper: G_hamburger ≤ G_hausdorff
    // ≤ the exact fraction in front of z_f (both lower bounds), for unbiased valid moments.
    const auto ds = distributions(300);
    for (size_t i = 0; i < ds.size(); ++i) {
        const double zf = receiver(int(i));
        const dvec4 b = ds[i].powers();
        double truth = 0;
        for (size_t j = 0; j < ds[i].z.size(); ++j) truth += ds[i].z[j] < zf ? ds[i].w[j] : 0;
        const double ham = hamburger(b, zf, 1e-6, dvec4(0.5)), hau = hausdorff(b, zf, 1e-6);
        EXPECT_LE(ham, hau + 1e-3) << i;
        EXPECT_LE(hau, truth + 1e-3) << i;
    }
}

}  // namespace sl
