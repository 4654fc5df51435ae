// error_metrics: how far a shadow image G is from a reference G, over the pixels a light
// reaches (elsewhere G does not change the image). Signs: the technique "leaks" where it is
// lighter than the reference (G smaller) and "over-darkens" where it is darker.
#pragma once

#include "image.h"

#include <filesystem>

namespace sl {

struct ShadowError {
    double rmse = 0.0;
    double max = 0.0;         // largest |G - G_ref|
    double p99 = 0.0;         // 99th percentile of |G - G_ref|
    double over005 = 0.0;     // fraction of reached pixels with |G - G_ref| > 0.05
    double leakArea = 0.0;    // fraction of reached pixels with G_ref - G > 0.1 (lit, should not be)
    double darkArea = 0.0;    // fraction of reached pixels with G - G_ref > 0.1
    size_t pixels = 0;        // reached pixels compared
};

// `shadow`, `reference`, `reached`: one channel (the first is used), same size. A NaN in
// `shadow` counts as an error of 1.
ShadowError measureShadowError(const Image& shadow, const Image& reference, const Image& reached);

// A heat map of G - G_ref: red where the technique leaks, blue where it over-darkens, white at
// |error| >= `scale`, black where it agrees, dark grey where the light does not reach.
Image errorHeatMap(const Image& shadow, const Image& reference, const Image& reached,
                   float scale = 0.25f);

}  // namespace sl
