// gaussian_exact: the stage contract's separable Gaussian in double, computed independently of
// the renderer's float weights: the expected values of `shadowlab probe gaussian`.
#pragma once

#include "image.h"

#include <vector>

namespace sl {

// w_0 .. w_r, w_k ∝ exp(−k² / 2σ²), w0 + 2·Σ w_k = 1; sigma <= 0 means r / 2 (the scenes'
// default). r = 0: {1}.
std::vector<double> exactGaussianWeights(int radius, double sigma);

// The blur of an RGBA `map` along x (if alongX), then along y (if alongY), clamp to edge:
// texel p = Σ_{k=-r..r} w_|k|·map(clamp(p + k·direction)), in double. Values per texel and
// channel, in Image's order.
std::vector<double> exactGaussianBlur(const Image& map, int radius, double sigma, bool alongX,
                                      bool alongY);

// How far a float32 pass may be from it: per pass (2r + 3)·u·max|map|, u = 2^-24 (the float
// weights' rounding, 2r + 1 rounded products and sums).
double gaussianRoundingBound(int radius, int passes, double maxAbs);

}  // namespace sl
