// techniques/evsm_common.glsl: the exponential warp shared by evsm2 and evsm4 (and the shadow
// pass that stores it): w(z) = e^{c z'}, z' = 2z − 1, and the Chebyshev bound on warped
// moments with a minimum variance that follows the warp's slope.
float evsmWarp(float z, float c) { return exp(c * (2.0 * z - 1.0)); }

float evsmPositiveLit(vec2 m, float zf, float c, float minVariance) {
    float w = evsmWarp(zf, c);
    float scale = c * w;
    return chebyshevUpperBound(m, w, minVariance * scale * scale);
}

