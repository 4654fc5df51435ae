// techniques/msm_hamburger.glsl: the canonical representation's support points (Peters & Klein
// 2015), which msm4-hausdorff and msm-soft need beyond G itself: Cholesky of the 3×3 Hankel
// matrix B of the biased moments, the quadratic c through (1, z_f, z_f²), its roots z2 ≤ z3.
// It solves the msm stage, so the student kit leaves it (and those two techniques) out; G
// itself always comes from the solution's momentShadowIntensity (msm.glsl).

// The canonical representation through z_f: roots (z2, z3) of the quadratic, from biased b.
vec2 msmRoots(vec4 b, float zf) {
    float D22 = max(b.y - b.x * b.x, 1e-10);
    float L32 = (b.z - b.x * b.y) / D22;
    float D33 = max(b.w - b.y * b.y - L32 * L32 * D22, 1e-10);
    float y2 = zf - b.x;
    float y3 = zf * zf - b.y - L32 * y2;
    vec3 c;
    c.z = y3 / D33;
    c.y = y2 / D22 - L32 * c.z;
    c.x = 1.0 - b.x * c.y - b.y * c.z;
    c /= max(max(abs(c.x), abs(c.y)), abs(c.z));
    float s = sqrt(max(c.y * c.y - 4.0 * c.x * c.z, 0.0));
    float q = -0.5 * (c.y + (c.y < 0.0 ? -s : s));
    float safeZ = c.z < 0.0 ? min(c.z, -1e-30) : max(c.z, 1e-30);
    float safeQ = q < 0.0 ? min(q, -1e-30) : max(q, 1e-30);
    float rA = clamp(q / safeZ, -1e10, 1e10);
    float rB = q == 0.0 ? rA : clamp(c.x / safeQ, -1e10, 1e10);
    return vec2(min(rA, rB), max(rA, rB));
}

// Blockers from moments (Peters et al. 2016): the canonical representation through z_f has
// support {z_f, z2, z3}; its weights (from moments 1, b1, b2: a 3×3 Vandermonde solve) tell
// which fraction lies in front of z_f and at which mean depth. Returns (fraction, mean depth).
vec2 msmBlockers(vec4 b, float zf, float alpha) {
    b = mix(b, vec4(0.5), alpha);
    vec2 z = msmRoots(b, zf);
    // Lagrange weights of the three nodes: w_i = E[Π_{j≠i} (x − x_j)] / Π_{j≠i} (x_i − x_j).
    float x0 = zf, x1 = z.x, x2 = z.y;
    float d1 = (x1 - x0) * (x1 - x2), d2 = (x2 - x0) * (x2 - x1);
    float w1 = abs(d1) > 1e-12 ? (b.y - b.x * (x0 + x2) + x0 * x2) / d1 : 0.0;
    float w2 = abs(d2) > 1e-12 ? (b.y - b.x * (x0 + x1) + x0 * x1) / d2 : 0.0;
    float fraction = 0.0, depth = 0.0;
    if (x1 < zf) { fraction += w1; depth += w1 * x1; }
    if (x2 < zf) { fraction += w2; depth += w2 * x2; }
    if (!(fraction > 1e-4)) return vec2(0.0, zf);
    return vec2(clamp(fraction, 0.0, 1.0), clamp(depth / fraction, 0.0, zf));
}
