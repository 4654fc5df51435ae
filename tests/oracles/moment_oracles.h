// CPU oracles of the Moment Shadow Mapping stage math (test-only code).
//
// The tests compare what the GLSL stages produce on llvmpipe with these functions.
// They are written from docs/stage_contract.md and from Peters & Klein (I3D 2015),
// never from a shader file, so that a shader bug and an oracle bug are unlikely to agree.
//
// Everything is computed in double precision: the GPU works in float32, so an oracle
// that is ~1e9 times more accurate makes "GPU vs oracle" differences measure the GPU's
// rounding (and bugs) only. Images are RGBA, row-major, 4 values per texel, row 0 first.
#pragma once

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace sl::oracle {

// float32's unit roundoff, 2^-24: the tests' tolerances are multiples of it.
inline constexpr double u = 1.0 / (1 << 24);

// ---------------------------------------------------------------- moments.glsl

// (lightDepth - near) / (far - near), clamped to [0, 1]. Precondition: far > near.
// (Parameters are not called near/far: those are macros in some Windows headers.)
inline double relativeDepth(double lightDepth, double zNear, double zFar) {
  return std::clamp((lightDepth - zNear) / (zFar - zNear), 0.0, 1.0);
}

// (b1, b2, b3, b4) = (z, z^2, z^3, z^4).
inline glm::dvec4 computeMoments(double z) {
  const double z2 = z * z;
  return {z, z2, z2 * z, z2 * z2};
}

// ---------------------------------------------------------------- images

namespace detail {
inline std::size_t texel(int x, int y, int w) {
  return (static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x)) * 4;
}
inline glm::dvec4 load(const std::vector<float>& img, int x, int y, int w) {
  const std::size_t i = texel(x, y, w);
  return {img[i], img[i + 1], img[i + 2], img[i + 3]};
}
inline glm::dvec4 load(const std::vector<double>& img, int x, int y, int w) {
  const std::size_t i = texel(x, y, w);
  return {img[i], img[i + 1], img[i + 2], img[i + 3]};
}
inline void store(std::vector<double>& img, int x, int y, int w, glm::dvec4 v) {
  const std::size_t i = texel(x, y, w);
  for (int c = 0; c < 4; ++c) img[i + c] = v[c];
}
}  // namespace detail

// One-sided Gaussian weights w[0..radius], w_k ∝ exp(-k²/(2σ²)), normalised so that
// w0 + 2·(w1 + … + wr) = 1. sigma <= 0 means radius / 2; radius <= 0 gives {1}.
inline std::vector<double> gaussianWeights(int radius, double sigma) {
  if (radius <= 0) return {1.0};
  if (sigma <= 0.0) sigma = radius / 2.0;
  std::vector<double> w(static_cast<std::size_t>(radius) + 1);
  double total = 0.0;
  for (int k = 0; k <= radius; ++k) {
    w[k] = std::exp(-double(k) * k / (2.0 * sigma * sigma));
    total += (k == 0 ? 1.0 : 2.0) * w[k];
  }
  for (double& v : w) v /= total;
  return w;
}

namespace detail {
// Shared by the float-input public function and the second (double) pass of the 2D blur.
template <typename Real>
std::vector<double> blur1D(const std::vector<Real>& src, int w, int h, int radius, double sigma,
                           bool dirX) {
  const std::vector<double> weights = gaussianWeights(radius, sigma);
  const int r = static_cast<int>(weights.size()) - 1;
  std::vector<double> dst(src.size(), 0.0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      glm::dvec4 sum(0.0);
      for (int k = -r; k <= r; ++k) {
        // Clamp to edge: the border texel is repeated.
        const int sx = dirX ? std::clamp(x + k, 0, w - 1) : x;
        const int sy = dirX ? y : std::clamp(y + k, 0, h - 1);
        sum += weights[std::abs(k)] * load(src, sx, sy, w);
      }
      store(dst, x, y, w, sum);
    }
  return dst;
}
}  // namespace detail

// One separable Gaussian pass: along rows (x) when dirX, else along columns (y).
inline std::vector<double> gaussianBlur1D(const std::vector<float>& src, int w, int h, int radius,
                                          double sigma, bool dirX) {
  return detail::blur1D(src, w, h, radius, sigma, dirX);
}

// The framework's two passes: x, then y. The intermediate image stays in double here
// (the GPU rounds it to float32; that difference is part of the comparison tolerance).
inline std::vector<double> gaussianBlur2D(const std::vector<float>& src, int w, int h, int radius,
                                          double sigma) {
  return detail::blur1D(detail::blur1D(src, w, h, radius, sigma, true), w, h, radius, sigma, false);
}

// Inclusive summed-area table: S(x, y) = Σ_{i<=x, j<=y} src(i, j), accumulated in double.
inline std::vector<double> summedAreaTable(const std::vector<float>& src, int w, int h) {
  std::vector<double> sat(src.size(), 0.0);
  for (int y = 0; y < h; ++y) {
    glm::dvec4 row(0.0);  // prefix sum of this row
    for (int x = 0; x < w; ++x) {
      row += detail::load(src, x, y, w);
      const glm::dvec4 above = y > 0 ? detail::load(sat, x, y - 1, w) : glm::dvec4(0.0);
      detail::store(sat, x, y, w, row + above);
    }
  }
  return sat;
}

namespace detail {
// Clipped box [x0, x1] × [y0, y1]; empty (x1 <= x0 or y1 <= y0) when it misses the map.
struct Box {
  double x0, x1, y0, y1;
};
inline Box clipBox(int w, int h, glm::dvec2 center, glm::dvec2 boxSize) {
  return {std::clamp(center.x - 0.5 * boxSize.x, 0.0, double(w)),
          std::clamp(center.x + 0.5 * boxSize.x, 0.0, double(w)),
          std::clamp(center.y - 0.5 * boxSize.y, 0.0, double(h)),
          std::clamp(center.y + 0.5 * boxSize.y, 0.0, double(h))};
}

// S at integer indices with S(-1, ·) = S(·, -1) = 0.
template <typename Real>
glm::dvec4 satAt(const std::vector<Real>& sat, int w, int i, int j) {
  if (i < 0 || j < 0) return glm::dvec4(0.0);
  return load(sat, i, j, w);
}

// Sum of the map over [0, ex] × [0, ey] for ex in [0, w], ey in [0, h]: S bilinearly
// interpolated at (ex - 1, ey - 1). Bilinear is exact here because the integral of a
// piecewise-constant image is bilinear inside every cell of the integer grid.
template <typename Real>
glm::dvec4 sumBelow(const std::vector<Real>& sat, int w, int h, double ex, double ey) {
  const double tx = ex - 1.0, ty = ey - 1.0;
  // Lower corner of the cell, kept in [-1, size - 2] so that i + 1 stays inside the table.
  const int i = std::clamp(static_cast<int>(std::floor(tx)), -1, std::max(w - 2, -1));
  const int j = std::clamp(static_cast<int>(std::floor(ty)), -1, std::max(h - 2, -1));
  const double fx = tx - i, fy = ty - j;  // in [0, 1]
  const glm::dvec4 s00 = satAt(sat, w, i, j), s10 = satAt(sat, w, i + 1, j);
  const glm::dvec4 s01 = satAt(sat, w, i, j + 1), s11 = satAt(sat, w, i + 1, j + 1);
  return (1 - fy) * ((1 - fx) * s00 + fx * s10) + fy * ((1 - fx) * s01 + fx * s11);
}
}  // namespace detail

// Mean of the map over the box (centre and size in texels; texel i covers [i, i+1)) clipped
// to [0, w] × [0, h], from the summed-area table `sat` (double from summedAreaTable, or the
// float32 table read back from the GPU). Returns 0 when the box misses the map.
template <typename Real>
glm::dvec4 satBoxAverage(const std::vector<Real>& sat, int w, int h, glm::dvec2 center,
                         glm::dvec2 boxSize) {
  const detail::Box b = detail::clipBox(w, h, center, boxSize);
  const double area = (b.x1 - b.x0) * (b.y1 - b.y0);
  if (!(b.x1 > b.x0 && b.y1 > b.y0)) return glm::dvec4(0.0);
  const glm::dvec4 sum = detail::sumBelow(sat, w, h, b.x1, b.y1) - detail::sumBelow(sat, w, h, b.x0, b.y1) -
                         detail::sumBelow(sat, w, h, b.x1, b.y0) + detail::sumBelow(sat, w, h, b.x0, b.y0);
  return sum / area;
}

// The same mean by brute force: every texel weighted by the area of it the box covers.
// Deliberately shares nothing with the SAT path (no table, no interpolation), so the two
// can cross-check each other.
inline glm::dvec4 boxAverageDirect(const std::vector<float>& src, int w, int h, glm::dvec2 center,
                                   glm::dvec2 boxSize) {
  const detail::Box b = detail::clipBox(w, h, center, boxSize);
  glm::dvec4 sum(0.0);
  double area = 0.0;
  for (int y = 0; y < h; ++y) {
    const double cy = std::min(b.y1, y + 1.0) - std::max(b.y0, double(y));
    if (cy <= 0.0) continue;
    for (int x = 0; x < w; ++x) {
      const double cx = std::min(b.x1, x + 1.0) - std::max(b.x0, double(x));
      if (cx <= 0.0) continue;
      sum += cx * cy * detail::load(src, x, y, w);
      area += cx * cy;
    }
  }
  return area > 0.0 ? sum / area : glm::dvec4(0.0);
}

// ---------------------------------------------------------------- msm.glsl

// Everything the Hamburger 4MSM computes on the way to G, exposed so that tests can
// check the intermediate canonical representation and not only the final number.
struct Msm4Detail {
  double G = 0.0;        // shadow intensity in [0, 1]
  glm::dvec4 biased{};   // b' = (1 - α)·b + α·(0.5, 0.5, 0.5, 0.5)
  double z2 = 0.0;       // the quadratic's roots, z2 <= z3 (unused when rank == 1)
  double z3 = 0.0;
  int rank = 3;          // numerical rank of the Hankel matrix: 3 normal, 2 or 1 degenerate
};

// Hamburger 4MSM (Peters & Klein 2015), in double.
//
// Idea: among all distributions of depth with the moments 1, b1', …, b4', find the one
// with support {zf, z2, z3} (the "canonical representation" through zf). Its support points
// other than zf are the roots of c1 + c2·z + c3·z² with B·c = (1, zf, zf²)ᵀ, B the Hankel
// matrix [[1,b1,b2],[b1,b2,b3],[b2,b3,b4]]. The weights follow from matching 1, b1', b2':
//   w_i·(z_i - z_j)·(z_i - z_k) = z_j·z_k - b1'·(z_j + z_k) + b2'   ({i, j, k} = {f, 2, 3})
// G is the weight in front of zf: 0 if zf <= z2; w2 if z2 < zf <= z3; 1 - w_f if zf > z3.
//
// Degenerate B (only possible at the boundary of the moment space: the depths take one or
// two distinct values, e.g. a point mass with α = 0, or depth exactly 0 or 1 where the
// bias vector adds no new support point) cannot be inverted. There the distribution is
// unique and G is its exact CDF, which is also the limit of the full algorithm:
//   rank 2: support = roots of the null vector of B, z² - L32·z + (b1'·L32 - b2') (from
//           Lᵀn = e3), and the same case split (w_f = 0 makes it the exact CDF);
//   rank 1: a point mass at b1', G = (zf > b1') ? 1 : 0.
// A pivot counts as zero below kPivotEps: entries are O(1) and the pivots carry an
// absolute rounding error of ~1e-15, so 1e-12 keeps ≥ 3 correct digits in a pivot used.
inline Msm4Detail msm4HamburgerDetail(glm::dvec4 b, double zf, double alpha) {
  constexpr double kPivotEps = 1e-12;
  constexpr double kFar = 1e30;  // a root "at infinity" (c3 ≈ 0) is clamped here
  Msm4Detail r;
  const glm::dvec4 bb = (1.0 - alpha) * b + alpha * glm::dvec4(0.5);
  r.biased = bb;
  const double b1 = bb.x, b2 = bb.y, b3 = bb.z, b4 = bb.w;

  // LDLᵀ (square-root-free Cholesky) of B: L = [[1,0,0],[b1,1,0],[b2,L32,1]], D = diag(1,D2,D3).
  const double D2 = b2 - b1 * b1;
  if (!(D2 > kPivotEps)) {
    r.rank = 1;
    r.z2 = r.z3 = b1;
    r.G = zf > b1 ? 1.0 : 0.0;
    return r;
  }
  const double L32 = (b3 - b1 * b2) / D2;
  const double D3 = (b4 - b2 * b2) - L32 * L32 * D2;

  double z2 = 0.0, z3 = 0.0;
  if (!(D3 > kPivotEps)) {
    r.rank = 2;
    // Roots of z² - L32·z + (b1·L32 - b2); its discriminant equals (L32 - 2·b1)² + 4·D2 > 0.
    const double s = std::sqrt((L32 - 2.0 * b1) * (L32 - 2.0 * b1) + 4.0 * D2);
    z2 = 0.5 * (L32 - s);
    z3 = 0.5 * (L32 + s);
  } else {
    // Solve B·c = (1, zf, zf²)ᵀ: L·y = v, then Lᵀ·c = D⁻¹·y.
    const double y1 = 1.0, y2 = zf - b1, y3 = zf * zf - b2 - L32 * y2;
    const double c3 = y3 / D3;
    const double c2 = y2 / D2 - L32 * c3;
    const double c1 = y1 - b1 * c2 - b2 * c3;
    // Roots of c1 + c2·z + c3·z², by the cancellation-free form of the quadratic formula.
    const double disc = std::max(c2 * c2 - 4.0 * c1 * c3, 0.0);  // > 0 in exact arithmetic
    const double q = -0.5 * (c2 + std::copysign(std::sqrt(disc), c2));
    double ra, rb;
    if (q == 0.0) {
      ra = rb = 0.0;  // c2 = 0 and c1·c3 = 0 with c3 != 0: double root at 0
    } else {
      ra = c3 != 0.0 ? q / c3 : std::copysign(kFar, q);
      rb = c1 / q;
    }
    ra = std::clamp(ra, -kFar, kFar);
    rb = std::clamp(rb, -kFar, kFar);
    z2 = std::min(ra, rb);
    z3 = std::max(ra, rb);
  }
  r.z2 = z2;
  r.z3 = z3;

  double G;
  if (zf <= z2) {
    G = 0.0;
  } else if (zf <= z3) {
    G = (zf * z3 - b1 * (zf + z3) + b2) / ((z3 - z2) * (zf - z2));
  } else {
    G = 1.0 - (z2 * z3 - b1 * (z2 + z3) + b2) / ((zf - z2) * (zf - z3));
  }
  r.G = std::clamp(G, 0.0, 1.0);
  return r;
}

// Shadow intensity G in [0, 1] (0 lit, 1 fully shadowed) of msm.glsl's momentShadowIntensity.
inline double msm4Hamburger(glm::dvec4 b, double zf, double alpha) {
  return msm4HamburgerDetail(b, zf, alpha).G;
}

}  // namespace sl::oracle
