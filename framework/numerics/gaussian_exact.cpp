// gaussian_exact: the contract's Gaussian in double (see the header).
#include "gaussian_exact.h"

#include <algorithm>
#include <cmath>

namespace sl {

std::vector<double> exactGaussianWeights(int radius, double sigma) {
    if (radius <= 0) return {1.0};
    const double s = sigma > 0.0 ? sigma : radius / 2.0;
    std::vector<double> w(size_t(radius) + 1);
    double total = 0.0;
    for (int k = 0; k <= radius; ++k) {
        w[size_t(k)] = std::exp(-double(k) * k / (2.0 * s * s));
        total += (k == 0 ? 1.0 : 2.0) * w[size_t(k)];
    }
    for (double& v : w) v /= total;
    return w;
}

std::vector<double> exactGaussianBlur(const Image& map, int radius, double sigma, bool alongX,
                                      bool alongY) {
    const int W = map.width, H = map.height, C = map.channels;
    std::vector<double> cur(map.pixels.begin(), map.pixels.end());
    const std::vector<double> w = exactGaussianWeights(radius, sigma);
    const int r = int(w.size()) - 1;
    for (int pass = 0; pass < 2; ++pass) {
        if (!(pass == 0 ? alongX : alongY)) continue;
        std::vector<double> next(cur.size(), 0.0);
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x)
                for (int k = -r; k <= r; ++k) {
                    const int sx = pass == 0 ? std::clamp(x + k, 0, W - 1) : x;
                    const int sy = pass == 1 ? std::clamp(y + k, 0, H - 1) : y;
                    const double wk = w[size_t(std::abs(k))];
                    for (int c = 0; c < C; ++c)
                        next[(size_t(y) * W + x) * C + c] += wk * cur[(size_t(sy) * W + sx) * C + c];
                }
        cur = std::move(next);
    }
    return cur;
}

double gaussianRoundingBound(int radius, int passes, double maxAbs) {
    const double u = std::ldexp(1.0, -24);
    return passes * (2.0 * std::max(radius, 0) + 3.0) * u * std::max(maxAbs, 1e-30);
}

}  // namespace sl
