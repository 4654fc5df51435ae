// Tests of the CPU oracles themselves (tests/oracles/moment_oracles.h).
//
// Other tests trust these oracles to judge the GPU stages, so here every expected value
// comes from somewhere else: closed-form values, hand computations, a brute-force second
// implementation, or a mathematical property (moment matching, lower-bound inequalities)
// that the oracle's code does not use.
#include "oracles/moment_oracles.h"

#include <gtest/gtest.h>
#include <glm/glm.hpp>

#include <array>
#include <cmath>
#include <random>
#include <vector>

namespace {
using namespace sl::oracle;

std::vector<float> constantImage(int w, int h, glm::vec4 v) {
  std::vector<float> img(static_cast<std::size_t>(w) * h * 4);
  for (std::size_t i = 0; i < img.size(); ++i) img[i] = v[static_cast<int>(i % 4)];
  return img;
}

std::vector<float> randomImage(int w, int h, std::mt19937& rng) {
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<float> img(static_cast<std::size_t>(w) * h * 4);
  for (float& v : img) v = u(rng);
  return img;
}

double at(const std::vector<double>& img, int w, int x, int y, int c) {
  return img[(static_cast<std::size_t>(y) * w + x) * 4 + c];
}

// Moments of a discrete depth distribution {(depth, weight)}.
struct Atom { double z, w; };
glm::dvec4 momentsOf(const std::vector<Atom>& atoms) {
  glm::dvec4 b(0.0);
  for (const Atom& a : atoms) b += a.w * computeMoments(a.z);
  return b;
}

// 1 / (vᵀ B⁻¹ v) with v = (1, zf, zf²): the weight the canonical representation puts on zf
// (the Christoffel function). Computed with a general 3×3 inverse, not with the oracle's LDLᵀ.
double christoffel(glm::dvec4 b, double zf) {
  const glm::dmat3 B(1, b.x, b.y, b.x, b.y, b.z, b.y, b.z, b.w);  // symmetric, so order is moot
  const glm::dvec3 v(1, zf, zf * zf);
  return 1.0 / glm::dot(v, glm::inverse(B) * v);
}

// ---------------------------------------------------------------- moments

TEST(Oracles, RelativeDepthIsAffineAndClamped) {
  EXPECT_DOUBLE_EQ(relativeDepth(3.0, 2.0, 6.0), 0.25);
  EXPECT_DOUBLE_EQ(relativeDepth(6.0, 2.0, 6.0), 1.0);
  EXPECT_DOUBLE_EQ(relativeDepth(1.0, 2.0, 6.0), 0.0);
  EXPECT_DOUBLE_EQ(relativeDepth(9.0, 2.0, 6.0), 1.0);
}

TEST(Oracles, MomentsOfPointMassesAndMixtures) {
  for (double d : {0.0, 0.25, 0.5, 1.0}) {
    const glm::dvec4 m = computeMoments(d);
    EXPECT_DOUBLE_EQ(m.x, d);
    EXPECT_DOUBLE_EQ(m.y, d * d);
    EXPECT_DOUBLE_EQ(m.z, d * d * d);
    EXPECT_DOUBLE_EQ(m.w, d * d * d * d);
  }
  // Half at 0.2, half at 0.6: (0.4, 0.2, 0.112, 0.0656) by hand.
  const glm::dvec4 b = momentsOf({{0.2, 0.5}, {0.6, 0.5}});
  EXPECT_NEAR(b.x, 0.4, 1e-15);
  EXPECT_NEAR(b.y, 0.2, 1e-15);
  EXPECT_NEAR(b.z, 0.112, 1e-15);
  EXPECT_NEAR(b.w, 0.0656, 1e-15);
}

// ---------------------------------------------------------------- Gaussian

TEST(Oracles, GaussianWeightsAreNormalisedPositiveDecreasing) {
  for (int r : {1, 2, 3, 8, 16})
    for (double sigma : {0.0, 0.7, 2.0, 5.0}) {
      const std::vector<double> w = gaussianWeights(r, sigma);
      ASSERT_EQ(w.size(), static_cast<std::size_t>(r) + 1);
      double total = w[0];
      for (int k = 1; k <= r; ++k) {
        total += 2.0 * w[k];
        EXPECT_GT(w[k], 0.0);
        EXPECT_LT(w[k], w[k - 1]);
        // The shape: w_k / w_0 = exp(-k²/(2σ²)), σ = r/2 when sigma <= 0.
        const double s = sigma > 0.0 ? sigma : r / 2.0;
        EXPECT_NEAR(w[k] / w[0], std::exp(-k * k / (2 * s * s)), 1e-14);
      }
      EXPECT_NEAR(total, 1.0, 1e-15);
    }
  EXPECT_EQ(gaussianWeights(0, 3.0), std::vector<double>{1.0});
  EXPECT_EQ(gaussianWeights(4, 0.0), gaussianWeights(4, 2.0));
}

TEST(Oracles, BlurOfConstantImageIsConstant) {
  const int w = 13, h = 7;
  const glm::vec4 v(0.25f, 0.5f, -3.0f, 7.0f);
  const std::vector<float> img = constantImage(w, h, v);
  for (bool dirX : {true, false}) {
    const std::vector<double> out = gaussianBlur1D(img, w, h, 5, 0.0, dirX);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        for (int c = 0; c < 4; ++c) EXPECT_NEAR(at(out, w, x, y, c), v[c], 1e-12);
  }
  const std::vector<double> out2 = gaussianBlur2D(img, w, h, 9, 3.0);  // radius > image height
  for (std::size_t i = 0; i < out2.size(); ++i) EXPECT_NEAR(out2[i], v[static_cast<int>(i % 4)], 1e-12);
}

TEST(Oracles, BlurOfImpulseIsTheKernel) {
  // An impulse far from every edge: the 1D response is w_|k| (symmetric about the impulse),
  // the 2D response the outer product w_|i|·w_|j|.
  const int w = 21, h = 17, cx = 10, cy = 8, r = 4;
  std::vector<float> img = constantImage(w, h, glm::vec4(0.0f));
  const glm::vec4 v(1.0f, 2.0f, 0.5f, 4.0f);
  for (int c = 0; c < 4; ++c) img[(static_cast<std::size_t>(cy) * w + cx) * 4 + c] = v[c];
  const std::vector<double> wt = gaussianWeights(r, 1.5);

  const std::vector<double> bx = gaussianBlur1D(img, w, h, r, 1.5, true);
  const std::vector<double> b2 = gaussianBlur2D(img, w, h, r, 1.5);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 4; ++c) {
        const int dx = std::abs(x - cx), dy = std::abs(y - cy);
        const double k1 = (y == cy && dx <= r) ? wt[dx] : 0.0;
        const double k2 = (dx <= r && dy <= r) ? wt[dx] * wt[dy] : 0.0;
        EXPECT_NEAR(at(bx, w, x, y, c), k1 * v[c], 1e-15);
        EXPECT_NEAR(at(b2, w, x, y, c), k2 * v[c], 1e-15);
      }
}

TEST(Oracles, BlurClampsToEdge) {
  // One row [a, b, c, d, e], radius 2, σ = 1. Left edge texel by hand: taps at -2, -1 read a.
  const std::vector<float> row = {1, 0, 0, 0, 2, 0, 0, 0, 3, 0, 0, 0, 4, 0, 0, 0, 5, 0, 0, 0};
  const double e1 = std::exp(-0.5), e2 = std::exp(-2.0), n = 1 + 2 * e1 + 2 * e2;
  const double left = (1 * (1 + e1 + e2) + 2 * e1 + 3 * e2) / n;   // a·(w0+w1+w2) + b·w1 + c·w2
  const double right = (5 * (1 + e1 + e2) + 4 * e1 + 3 * e2) / n;  // mirror image at the end
  const double second = (1 * (e1 + e2) + 2 + 3 * e1 + 4 * e2) / n; // tap -2 clamps to a
  const std::vector<double> out = gaussianBlur1D(row, 5, 1, 2, 1.0, true);
  EXPECT_NEAR(at(out, 5, 0, 0, 0), left, 1e-15);
  EXPECT_NEAR(at(out, 5, 4, 0, 0), right, 1e-15);
  EXPECT_NEAR(at(out, 5, 1, 0, 0), second, 1e-15);
  // The same column blurred along y gives the same numbers.
  const std::vector<double> col = gaussianBlur1D(row, 1, 5, 2, 1.0, false);
  EXPECT_NEAR(at(col, 1, 0, 0, 0), left, 1e-15);
  EXPECT_NEAR(at(col, 1, 0, 4, 0), right, 1e-15);
}

TEST(Oracles, BlurAlongYIsBlurAlongXTransposed) {
  std::mt19937 rng(7);
  const int w = 9, h = 6;
  const std::vector<float> img = randomImage(w, h, rng);
  std::vector<float> t(img.size());
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 4; ++c) t[(static_cast<std::size_t>(x) * h + y) * 4 + c] = img[(static_cast<std::size_t>(y) * w + x) * 4 + c];
  const std::vector<double> ay = gaussianBlur1D(img, w, h, 3, 0.0, false);
  const std::vector<double> ax = gaussianBlur1D(t, h, w, 3, 0.0, true);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 4; ++c) EXPECT_DOUBLE_EQ(at(ay, w, x, y, c), at(ax, h, y, x, c));
}

// ---------------------------------------------------------------- SAT

TEST(Oracles, SatOfOnesIsTheCountOfTexels) {
  const int w = 11, h = 5;
  const std::vector<double> sat = summedAreaTable(constantImage(w, h, glm::vec4(1.0f)), w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 4; ++c) EXPECT_EQ(at(sat, w, x, y, c), double((x + 1) * (y + 1)));
}

TEST(Oracles, BoxAverageByHand) {
  // One row [1, 2, 3, 4]. Box [0.75, 3.25]: 0.25·1 + 2 + 3 + 0.25·4 = 6.25 over 2.5 texels.
  const std::vector<float> row = {1, 1, 1, 1, 2, 2, 2, 2, 3, 3, 3, 3, 4, 4, 4, 4};
  const std::vector<double> sat = summedAreaTable(row, 4, 1);
  const glm::dvec4 a = satBoxAverage(sat, 4, 1, {2.0, 0.5}, {2.5, 1.0});
  const glm::dvec4 d = boxAverageDirect(row, 4, 1, {2.0, 0.5}, {2.5, 1.0});
  EXPECT_NEAR(a.x, 2.5, 1e-14);
  EXPECT_NEAR(d.x, 2.5, 1e-14);
  // Box [-1, 2] is clipped to [0, 2]: (1 + 2) / 2. Box bigger than the map: the mean, 2.5.
  EXPECT_NEAR(satBoxAverage(sat, 4, 1, {0.5, 0.5}, {3.0, 1.0}).y, 1.5, 1e-14);
  EXPECT_NEAR(boxAverageDirect(row, 4, 1, {0.5, 0.5}, {3.0, 1.0}).y, 1.5, 1e-14);
  EXPECT_NEAR(satBoxAverage(sat, 4, 1, {2.0, 0.5}, {40.0, 40.0}).z, 2.5, 1e-14);
  // A one-texel box on a texel returns that texel.
  EXPECT_NEAR(satBoxAverage(sat, 4, 1, {2.5, 0.5}, {1.0, 1.0}).w, 3.0, 1e-14);
}

TEST(Oracles, SatBoxAverageMatchesBruteForce) {
  std::mt19937 rng(2015);
  struct Size { int w, h; };
  for (Size s : {Size{1, 1}, Size{1, 7}, Size{7, 1}, Size{5, 3}, Size{16, 9}, Size{32, 32}}) {
    const std::vector<float> img = randomImage(s.w, s.h, rng);
    const std::vector<double> sat = summedAreaTable(img, s.w, s.h);
    const std::vector<float> satF(sat.begin(), sat.end());  // as read back from the GPU
    std::vector<std::pair<glm::dvec2, glm::dvec2>> boxes;  // (centre, size)
    std::uniform_real_distribution<double> ux(0.0, s.w), uy(0.0, s.h);
    std::uniform_real_distribution<double> us(1.0, 2.0 * std::max(s.w, s.h) + 2.0);
    for (int i = 0; i < 200; ++i) boxes.push_back({{ux(rng), uy(rng)}, {us(rng), us(rng)}});
    // Hanging over each edge and each corner, on exact edges, and covering everything.
    const double W = s.w, H = s.h;
    for (double cx : {0.0, 0.3, W / 2, W - 0.3, W})
      for (double cy : {0.0, 0.3, H / 2, H - 0.3, H}) {
        boxes.push_back({{cx, cy}, {2.7, 3.1}});
        boxes.push_back({{cx, cy}, {1.0, 1.0}});
        boxes.push_back({{cx, cy}, {2 * W + 5, 2 * H + 5}});
      }
    for (const auto& [c, b] : boxes) {
      const glm::dvec4 ref = boxAverageDirect(img, s.w, s.h, c, b);
      const glm::dvec4 fromSat = satBoxAverage(sat, s.w, s.h, c, b);
      const glm::dvec4 fromSatF = satBoxAverage(satF, s.w, s.h, c, b);
      for (int k = 0; k < 4; ++k) {
        ASSERT_NEAR(fromSat[k], ref[k], 1e-10) << s.w << "x" << s.h << " c=(" << c.x << "," << c.y
                                               << ") size=(" << b.x << "," << b.y << ")";
        // A float32 table loses absolute precision ~ total·2^-24, amplified by 1/area.
        ASSERT_NEAR(fromSatF[k], ref[k], 1e-5 * s.w * s.h);
      }
    }
  }
}

// ---------------------------------------------------------------- MSM

constexpr double kAlphaFloat = 3e-5;  // the contract's default moment bias

TEST(Oracles, MsmPointMass) {
  for (double d : {0.05, 0.2, 0.5, 0.8, 0.95}) {
    const glm::dvec4 b = computeMoments(d);
    // zf on the occluder itself: nothing lies strictly in front of it (no self-shadowing).
    EXPECT_EQ(msm4Hamburger(b, d, 0.0), 0.0) << "d=" << d;
    for (double zf = 0.0; zf <= 1.0; zf += 0.005) {
      const double dist = std::abs(zf - d);
      if (dist < 0.01) continue;
      // α = 0: a point mass is the boundary of the moment space, so G is its exact CDF.
      EXPECT_EQ(msm4Hamburger(b, zf, 0.0), zf > d ? 1.0 : 0.0) << "d=" << d << " zf=" << zf;
      // α = 3e-5 turns the input into (1-α)·δ_d + α/2·(δ_0 + δ_1). G is a lower bound of the
      // mass in front of zf, which is α/2 before d and 1 - α/2 after it (for 0 < zf < 1).
      const double g = msm4Hamburger(b, zf, kAlphaFloat);
      const double front = zf < d ? kAlphaFloat / 2 : 1 - kAlphaFloat / 2;
      EXPECT_LE(g, front + 1e-12) << "d=" << d << " zf=" << zf;
      // Behind the occluder the bound is not tight: MSM's known light leaking, worst for
      // d = 0.5 (G(0.51) = 0.930), fading with distance (G(0.55) = 0.997).
      if (zf > d) {
        EXPECT_GE(g, dist < 0.05 ? 0.9 : 0.995) << "d=" << d << " zf=" << zf;
      }
    }
  }
}

TEST(Oracles, MsmTwoEqualPointMasses) {
  const glm::dvec4 b = momentsOf({{0.2, 0.5}, {0.6, 0.5}});
  EXPECT_NEAR(msm4Hamburger(b, 0.4, 0.0), 0.5, 1e-12);
  EXPECT_EQ(msm4Hamburger(b, 0.1, 0.0), 0.0);
  EXPECT_NEAR(msm4Hamburger(b, 0.9, 0.0), 1.0, 1e-12);
  EXPECT_NEAR(msm4Hamburger(b, 0.4, kAlphaFloat), 0.5, 1e-3);
  EXPECT_NEAR(msm4Hamburger(b, 0.1, kAlphaFloat), 0.0, 1e-3);
  EXPECT_NEAR(msm4Hamburger(b, 0.9, kAlphaFloat), 1.0, 1e-3);
}

TEST(Oracles, MsmThreePointDistribution) {
  // {0.1: 0.3, 0.5: 0.3, 0.8: 0.4} has full-rank B. When zf is one of its atoms, the
  // canonical representation through zf is the distribution itself, so G is exactly the
  // mass strictly in front of zf.
  const glm::dvec4 b = momentsOf({{0.1, 0.3}, {0.5, 0.3}, {0.8, 0.4}});
  EXPECT_NEAR(msm4Hamburger(b, 0.1, 0.0), 0.0, 1e-9);
  EXPECT_NEAR(msm4Hamburger(b, 0.5, 0.0), 0.3, 1e-9);
  EXPECT_NEAR(msm4Hamburger(b, 0.8, 0.0), 0.6, 1e-9);
  // Between atoms G is only a bound. Chebyshev–Markov–Stieltjes: for any distribution with
  // these moments, G(zf) <= P(z < zf) <= P(z <= zf) <= G(zf) + w_f, w_f = 1 / (vᵀB⁻¹v).
  // At zf = 0.3 the true P is 0.3, so G(0.3) lies in [0.3 - w_f, 0.3].
  const double g = msm4Hamburger(b, 0.3, 0.0);
  EXPECT_LE(g, 0.3 + 1e-12);
  EXPECT_GE(g, 0.3 - christoffel(b, 0.3) - 1e-12);
  EXPECT_GE(g, 0.0);
}

TEST(Oracles, MsmCanonicalRepresentationMatchesAllMoments) {
  // For random distributions, check what the closed-form weights never used: the 3-point
  // distribution on {zf, z2, z3} (weights from a plain Vandermonde solve of the moments 1,
  // b1', b2') also reproduces b3' and b4', its weights are >= 0, the weight on zf is the
  // Christoffel function, G is the weight in front of zf, and G bounds the true CDF.
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int checked = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    // Atom i lies in the middle 80% of [i/n, (i+1)/n): atoms closer than ~0.03 make B so
    // ill-conditioned (D3 ~ 1e-9) that double itself only gives ~5 digits of the weights.
    std::vector<Atom> atoms(3 + trial % 4);
    const double n = static_cast<double>(atoms.size());
    double total = 0.0;
    for (std::size_t i = 0; i < atoms.size(); ++i)
      total += (atoms[i] = {(static_cast<double>(i) + 0.1 + 0.8 * u(rng)) / n, 0.05 + u(rng)}).w;
    for (Atom& a : atoms) a.w /= total;
    const double alpha = std::array<double, 3>{0.0, kAlphaFloat, 1e-3}[trial % 3];
    const double zf = u(rng);
    const Msm4Detail r = msm4HamburgerDetail(momentsOf(atoms), zf, alpha);
    if (r.rank != 3) continue;  // near-coincident atoms; the degenerate paths are tested below
    ++checked;
    const glm::dvec4 bb = r.biased;
    const double s[3] = {zf, r.z2, r.z3};
    // Columns are (1, s_i, s_i²): V·w = (1, b1', b2').
    const glm::dmat3 V(1, s[0], s[0] * s[0], 1, s[1], s[1] * s[1], 1, s[2], s[2] * s[2]);
    const glm::dvec3 wts = glm::inverse(V) * glm::dvec3(1.0, bb.x, bb.y);
    double m3 = 0.0, m4 = 0.0, front = 0.0;
    for (int i = 0; i < 3; ++i) {
      m3 += wts[i] * std::pow(s[i], 3);
      m4 += wts[i] * std::pow(s[i], 4);
      if (s[i] < zf) front += wts[i];
      EXPECT_GE(wts[i], -1e-6);
    }
    EXPECT_NEAR(m3, bb.z, 1e-6);
    EXPECT_NEAR(m4, bb.w, 1e-6);
    EXPECT_NEAR(wts[0], christoffel(bb, zf), 1e-6);
    EXPECT_NEAR(r.G, front, 1e-6);
    // Bounds against the true (biased) distribution: (1-α)·atoms + α/2 at 0 and at 1.
    double below = alpha / 2 * (zf > 0.0), belowEq = alpha / 2 * (zf >= 0.0) + alpha / 2 * (zf >= 1.0);
    for (const Atom& a : atoms) {
      below += (1 - alpha) * a.w * (a.z < zf);
      belowEq += (1 - alpha) * a.w * (a.z <= zf);
    }
    EXPECT_LE(r.G, below + 1e-6);
    EXPECT_GE(r.G + wts[0], belowEq - 1e-6);
  }
  EXPECT_GT(checked, 1900);
}

TEST(Oracles, MsmUniformDistributionIsMonotoneLowerBound) {
  const glm::dvec4 b(1.0 / 2, 1.0 / 3, 1.0 / 4, 1.0 / 5);  // E[z^k] for z uniform on [0, 1]
  for (double alpha : {0.0, kAlphaFloat}) {
    double previous = 0.0;
    for (int i = -100; i <= 1100; ++i) {
      const double zf = i / 1000.0;
      const double g = msm4Hamburger(b, zf, alpha);
      ASSERT_GE(g, 0.0);
      ASSERT_LE(g, 1.0);
      ASSERT_GE(g, previous - 1e-12) << "zf=" << zf;
      if (alpha == 0.0) {
        ASSERT_LE(g, std::clamp(zf, 0.0, 1.0) + 1e-12) << "zf=" << zf;  // a bound of P(z < zf)
      }
      previous = g;
    }
    EXPECT_EQ(msm4Hamburger(b, -0.1, alpha), 0.0);
    EXPECT_GT(msm4Hamburger(b, 1.1, alpha), 0.9);
  }
}

TEST(Oracles, MsmDegenerateInputsAreExactAndFinite) {
  // With α = 1 every input becomes half at 0 and half at 1.
  EXPECT_EQ(msm4Hamburger(glm::dvec4(0.3), 0.0, 1.0), 0.0);
  EXPECT_NEAR(msm4Hamburger(glm::dvec4(0.3), 0.5, 1.0), 0.5, 1e-12);
  EXPECT_NEAR(msm4Hamburger(glm::dvec4(0.3), 1.5, 1.0), 1.0, 1e-12);
  // Depth exactly 0 (or 1) with α: only the depths 0 and 1 occur, with masses 1 - α/2, α/2.
  EXPECT_NEAR(msm4Hamburger(computeMoments(0.0), 0.5, kAlphaFloat), 1 - kAlphaFloat / 2, 1e-9);
  EXPECT_NEAR(msm4Hamburger(computeMoments(1.0), 0.5, kAlphaFloat), kAlphaFloat / 2, 1e-9);

  std::vector<glm::dvec4> inputs = {glm::dvec4(0.0), glm::dvec4(-1.0), glm::dvec4(1.0)};
  for (double d : {0.0, 1e-8, 1e-4, 0.5, 1 - 1e-8, 1.0}) inputs.push_back(computeMoments(d));
  inputs.push_back(momentsOf({{0.0, 0.5}, {1.0, 0.5}}));
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> garbage(-2.0, 2.0);  // not moments at all
  for (int i = 0; i < 200; ++i) inputs.push_back({garbage(rng), garbage(rng), garbage(rng), garbage(rng)});
  for (const glm::dvec4& b : inputs)
    for (double alpha : {0.0, kAlphaFloat, 1e-3, 1.0})
      for (double zf : {-0.5, 0.0, 1e-8, 1e-4, 0.25, 0.5, 1 - 1e-8, 1.0, 1.5}) {
        const double g = msm4Hamburger(b, zf, alpha);
        ASSERT_TRUE(std::isfinite(g)) << b.x << " " << b.y << " " << b.z << " " << b.w << " zf=" << zf;
        ASSERT_GE(g, 0.0);
        ASSERT_LE(g, 1.0);
      }
}

}  // namespace
