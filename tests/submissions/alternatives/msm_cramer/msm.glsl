// ALTERNATIVE: Cramer's rule (the adjugate of the Hankel matrix of the central moments)
// instead of a Cholesky factorisation to find the quadratic's coefficients. Still correct:
// B·c = (1, zf, zf²)ᵀ has one solution, both compute it up to a scale the roots ignore,
// and the roots and weights are then the reference's.
// msm.glsl: shadow intensity from four filtered moments, Hamburger 4MSM.
// Stage contract: docs/stage_contract.md.
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

    // 2-3. Solve B·c = (1, zf, zf²)ᵀ by Cramer's rule instead of a Cholesky factorisation.
    //    Done naively on the raw moments, the cofactors (b2·b4 - b3², ...) cancel
    //    catastrophically: they are O(α) differences of O(1) products, and float32 loses them
    //    (G errors up to ~1 against a float64 oracle). So the polynomial is written in the
    //    shifted variable w = z - b1, i.e. the Hankel matrix of the *central* moments
    //        H = | 1   0   μ2 |      μ2 = b2 - b1²,  μ3 = b3 - 3·b1·b2 + 2·b1³,
    //            | 0   μ2  μ3 |      μ4 = b4 - 4·b1·b3 + 6·b1²·b2 - 3·b1⁴,
    //            | μ2  μ3  μ4 |
    //    (the same change of basis the Cholesky factor L performs), and H·c = (1, w, w²)ᵀ,
    //    w = zf - b1, is solved with H's adjugate: c = adj(H)·(1, w, w²)ᵀ / det(H).
    //    Only c's direction matters for the roots, so the division by det(H) is skipped
    //    altogether: no pivot can be zero and nothing needs a floor (a det(H) that rounding
    //    made negative would only flip c's sign, which leaves the roots alone).
    float m = b.x;
    float mu2 = b.y - m * m;
    float mu3 = b.z - m * (3.0 * b.y - 2.0 * m * m);
    float mu4 = b.w - m * (4.0 * b.z - m * (6.0 * b.y - 3.0 * m * m));
    float A00 = mu2 * mu4 - mu3 * mu3;
    float A01 = mu2 * mu3;
    float A02 = -mu2 * mu2;
    float A11 = mu4 - mu2 * mu2;
    float A12 = -mu3;
    float A22 = mu2;
    float w = zf - m;
    vec3 rhs = vec3(1.0, w, w * w);
    vec3 c = vec3(dot(vec3(A00, A01, A02), rhs),
                  dot(vec3(A01, A11, A12), rhs),
                  dot(vec3(A02, A12, A22), rhs));
    //    Scaled to max |ci| = 1 as in the reference (guarded: c = 0 only if H had rank 1).
    c /= max(max(max(abs(c.x), abs(c.y)), abs(c.z)), kTinyDenominator);

    // 4. Roots of c3·w² + c2·w + c1 = 0.
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
    //    (roots in w; back to depths z = w + b1.)
    float z2 = min(rootA, rootB) + m;
    float z3 = max(rootA, rootB) + m;

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
