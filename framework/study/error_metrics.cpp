// error_metrics: shadow error statistics and heat maps (see error_metrics.h).
#include "error_metrics.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace sl {
namespace {

void checkSizes(const Image& a, const Image& b, const Image& m) {
    if (a.width != b.width || a.height != b.height || a.width != m.width || a.height != m.height)
        throw std::invalid_argument("measureShadowError: images of different sizes");
}

}  // namespace

ShadowError measureShadowError(const Image& shadow, const Image& reference, const Image& reached) {
    checkSizes(shadow, reference, reached);
    ShadowError e;
    std::vector<double> abs;
    double sq = 0.0;
    for (int y = 0; y < shadow.height; ++y)
        for (int x = 0; x < shadow.width; ++x) {
            if (reached.at(x, y, 0) < 0.5f) continue;
            const double g = shadow.at(x, y, 0), r = reference.at(x, y, 0);
            const double d = std::isfinite(g) ? g - r : 1.0;
            sq += d * d;
            abs.push_back(std::abs(d));
            e.over005 += std::abs(d) > 0.05;
            e.leakArea += d < -0.1;
            e.darkArea += d > 0.1;
        }
    e.pixels = abs.size();
    if (abs.empty()) return e;
    const double n = double(abs.size());
    e.rmse = std::sqrt(sq / n);
    // Nearest-rank percentile: the smallest error at least 99% of pixels do not exceed.
    const size_t rank = size_t(std::ceil(0.99 * n)) - 1;
    std::nth_element(abs.begin(), abs.begin() + long(rank), abs.end());
    e.p99 = abs[rank];
    e.max = *std::max_element(abs.begin(), abs.end());
    e.over005 /= n;
    e.leakArea /= n;
    e.darkArea /= n;
    return e;
}

Image errorHeatMap(const Image& shadow, const Image& reference, const Image& reached,
                   float scale) {
    checkSizes(shadow, reference, reached);
    Image out(shadow.width, shadow.height, 3);
    for (int y = 0; y < shadow.height; ++y)
        for (int x = 0; x < shadow.width; ++x) {
            if (reached.at(x, y, 0) < 0.5f) {
                for (int c = 0; c < 3; ++c) out.at(x, y, c) = 0.12f;
                continue;
            }
            const float g = shadow.at(x, y, 0);
            const float d = std::isfinite(g) ? g - reference.at(x, y, 0) : 1.0f;
            const float t = std::min(std::abs(d) / scale, 1.0f);
            // leak (d < 0): black -> red -> white; over-darkening: black -> blue -> white.
            const float main = std::min(2.0f * t, 1.0f), rest = std::max(2.0f * t - 1.0f, 0.0f);
            out.at(x, y, 0) = d < 0 ? main : rest;
            out.at(x, y, 1) = rest;
            out.at(x, y, 2) = d < 0 ? rest : main;
        }
    return out;
}

}  // namespace sl
