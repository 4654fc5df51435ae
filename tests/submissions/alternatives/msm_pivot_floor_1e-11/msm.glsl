// ALTERNATIVE: pivot floors kMinD22 = kMinD33 = 1e-11 instead of the reference's 1e-10. Still correct:
// the floors only turn a zero or negative pivot (rounding noise) into a tiny positive one, and any
// floor far below the real pivots and far above 0 drives the solve to the same singular limit.
// msm.glsl: shadow intensity from four filtered moments, Hamburger 4MSM.
// Reference solution. Stage contract: docs/stage_contract.md.
//
// Peters & Klein, "Moment Shadow Mapping" (I3D 2015), Algorithm 3 (Hamburger 4MSM).
// The filtered texel holds b = (b1, b2, b3, b4), the first four power moments of the depth
// distribution the filter kernel sees. Many distributions share these moments; we return
// the smallest fraction of occluders in front of the fragment depth zf that any of them
// can have (a sharp lower bound). It is reached by the distribution with three point
// masses at z1 = zf, z2, z3 (the "canonical representation" through zf), and the shadow
// intensity is the weight of those support points that lie in front of zf.
//
// uMomentBias is α, declared by the framework before this file is included
// (`uniform float uMomentBias;`). Default 3e-5, tuned in the paper for moments stored as
// float32; a scene may override it.

// Pivot floors for the LDLᵀ factorisation. With the default α the variance pivot satisfies
// D22 >= α/4 (= 7.5e-6) in exact arithmetic, so its floor only acts when α was set to ~0.
// D33 has no such bound (see step 2): for depths at 0 and 1 only it is 0, and float32
// computes it as rounding noise of either sign (~1e-7 near depth 1). Flooring it at 1e-10
// turns "zero or negative" into "tiny positive", which drives the solution to its correct
// singular limit (support points 0 and 1) instead of to inf / NaN; real D33 values are
// hardly ever below it.
const float kMinD22 = 1e-11;
const float kMinD33 = 1e-11;
// Roots are capped at ±kFarRoot (c3 ≈ 0 sends one root to infinity, see below). The
// weight formulas then reach their limit to ~1/kFarRoot relative, below float32 epsilon,
// and their products (<= ~4e20) stay finite.
const float kFarRoot = 1e10;
// Smallest denominator divided by; every denominator guarded with it is positive in exact
// arithmetic and can only reach 0 by underflow (denormals may be flushed to zero).
const float kTinyDenominator = 1e-30;

// x / y capped to [-kFarRoot, kFarRoot]; y = 0 counts as +0, so 0 / 0 = 0. Never inf or NaN.
float msmCappedQuotient(float x, float y)
{
    float safeY = (y < 0.0) ? min(y, -kTinyDenominator) : max(y, kTinyDenominator);
    return clamp(x / safeY, -kFarRoot, kFarRoot);
}

// Shadow intensity G in [0, 1] (0: lit, 1: fully shadowed) of a fragment at relative depth
// zf (depth bias already subtracted) behind a filtered texel with moments b.
float momentShadowIntensity(vec4 b, float zf)
{
    // 1. Moment bias: b' = (1 - α)·b + α·(0.5, 0.5, 0.5, 0.5).
    //    (0.5, 0.5, 0.5, 0.5) are the moments of two equal point masses at depths 0 and 1
    //    (0.5·0^j + 0.5·1^j). Filtered moments often sit on (or, after float32 rounding,
    //    just outside) the boundary of the moment space: a single depth, or two, make the
    //    Hankel matrix B singular, and then the rounding errors decide the sign of its
    //    pivots. Mixing in α of a distribution that spans the whole depth range gives
    //    B' = (1 - α)·B + α·B0 with B0 = ½·v(0)v(0)ᵀ + ½·v(1)v(1)ᵀ, v(z) = (1, z, z²).
    //    B' is positive definite unless all the depth lies at exactly 0 and 1 (B0's kernel
    //    is the polynomial z·(z - 1)), and its variance pivot is D22 >= α/4, well above the
    //    ~1e-7 rounding noise of float32 moments. The price: G is off by about α/2 even for
    //    a single depth, and the bound leaks a little more light near occluders. A larger
    //    α is more robust and less accurate.
    b = mix(b, vec4(0.5), uMomentBias);

    // 2. LDLᵀ (square-root-free Cholesky) factorisation of the Hankel matrix
    //        B = | 1   b1  b2 |        L = | 1   0    0 |      D = diag(1, D22, D33)
    //            | b1  b2  b3 |            | b1  1    0 |
    //            | b2  b3  b4 |            | b2  L32  1 |
    //    D22 = b2 - b1² is the variance of the depth. D33 = b4 - b2² - L32²·D22 is the mean
    //    square of the best-fitting monic quadratic: it vanishes when the depth takes at most
    //    two values, e.g. a texel that sees nothing but the far plane (b = (1,1,1,1): after
    //    the bias all of its mass is at 0 and 1). Both pivots are floored before dividing.
    float D22 = max(b.y - b.x * b.x, kMinD22);
    float L32 = (b.z - b.x * b.y) / D22;
    float D33 = max(b.w - b.y * b.y - L32 * L32 * D22, kMinD33);

    // 3. Solve B·c = (1, zf, zf²)ᵀ. The polynomial c1 + c2·z + c3·z² vanishes exactly at
    //    the two support points z2, z3 other than zf of the canonical representation.
    //    Forward substitution L·y = (1, zf, zf²)ᵀ (y1 = 1):
    float y2 = zf - b.x;
    float y3 = zf * zf - b.y - L32 * y2;
    //    then Lᵀ·c = D⁻¹·y, from the bottom up:
    vec3 c;
    c.z = y3 / D33;
    c.y = y2 / D22 - L32 * c.z;
    c.x = 1.0 - b.x * c.y - b.y * c.z;
    //    Only c's direction matters for the roots. Scaling it to max |ci| = 1 keeps c2² and
    //    4·c1·c3 finite even when the floored pivots made c huge. (c != 0: if c2 = c3 = 0
    //    then c1 = 1.)
    c /= max(max(abs(c.x), abs(c.y)), abs(c.z));

    // 4. Roots of c3·z² + c2·z + c1 = 0.
    //    The discriminant is positive in exact arithmetic (B' is positive definite), so
    //    clamp its rounding noise to >= 0 before the square root.
    //    Cancellation-free quadratic formula: q = -(c2 + sign(c2)·sqrt(disc)) / 2 adds two
    //    numbers of the same sign, and the roots are q / c3 and c1 / q. The textbook
    //    (-c2 ± sqrt(disc)) / (2·c3) loses the root near [0, 1] to cancellation when c3 is
    //    small, which happens at two fragment depths zf of every texel.
    //    Degenerate quadratic c3 ≈ 0: the polynomial is (nearly) linear, one root runs off
    //    to ±infinity and the canonical representation gives it weight -> 0. q / c3 is then
    //    capped at ±kFarRoot, where the weight formulas of step 5 evaluate to their limit
    //    (the two-point distribution {zf, c1 / q}); G is continuous as c3 changes sign.
    float sqrtDiscriminant = sqrt(max(c.y * c.y - 4.0 * c.x * c.z, 0.0));
    float q = -0.5 * (c.y + (c.y < 0.0 ? -sqrtDiscriminant : sqrtDiscriminant));
    float rootA = msmCappedQuotient(q, c.z);
    //    q = 0 only if c2 = 0 and disc = 0: a double root at q / c3 = 0.
    float rootB = (q == 0.0) ? rootA : msmCappedQuotient(c.x, q);
    float z2 = min(rootA, rootB);
    float z3 = max(rootA, rootB);

    // 5. Weights of the canonical representation {z1 = zf, z2, z3}. Matching the moments
    //    1, b1, b2 of a three-point distribution gives, for {i, j, k} = {1, 2, 3},
    //        wi = (zj·zk - b1·(zj + zk) + b2) / ((zi - zj)·(zi - zk)).
    //    G sums the weights of the support points strictly in front of zf:
    //      zf <= z2       : nothing in front,        G = 0;
    //      z2 < zf <= z3  : only z2 in front,         G = w2;
    //      z3 < zf        : everything except zf,     G = 1 - w1.
    //    Each denominator is a product of positive differences in its branch; the floor
    //    only guards against underflow. Clamping to [0, 1] removes the rounding overshoot.
    float G;
    if (z3 < zf) {
        float w1 = (z2 * z3 - b.x * (z2 + z3) + b.y)
                 / max((zf - z2) * (zf - z3), kTinyDenominator);
        G = 1.0 - w1;
    } else if (z2 < zf) {
        float w2 = (zf * z3 - b.x * (zf + z3) + b.y)
                 / max((z3 - z2) * (zf - z2), kTinyDenominator);
        G = w2;
    } else {
        G = 0.0;
    }
    return clamp(G, 0.0, 1.0);
}
