// msm_exact: exact 4MSM in long double (see the header). The canonical representation through
// zf has support {zf, z2, z3}, where z2, z3 are the roots of c1 + c2·z + c3·z² and
// c ∝ B⁻¹·(1, zf, zf²)ᵀ. Only c's direction matters, so c = adj(B)·v: no division by det(B),
// and for a singular B (rank 2) adj(B) ∝ n·nᵀ points at the null vector n, whose polynomial
// has the two support points of the (then unique) distribution as its roots.
#include "msm_exact.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sl {
namespace {

using R = long double;

// Weight of support point zi of {zi, zj, zk} matching the moments 1, b1, b2.
R weight(R zi, R zj, R zk, R b1, R b2) {
    return (zj * zk - b1 * (zj + zk) + b2) / ((zi - zj) * (zi - zk));
}

// Two real roots of c1 + c2·z + c3·z² (c3 != 0), cancellation-free; lo <= hi.
void roots(R c1, R c2, R c3, R& lo, R& hi) {
    const R disc = std::max<R>(c2 * c2 - 4 * c1 * c3, 0);  // >= 0 for a valid B
    const R q = -0.5L * (c2 + std::copysign(std::sqrt(disc), c2));
    const R r1 = q / c3, r2 = q != 0 ? c1 / q : r1;
    lo = std::min(r1, r2);
    hi = std::max(r1, r2);
}

// The solver. `project`: a B' that is not positive semidefinite through its last pivot only
// (det < 0, variance > 0) is taken at the boundary of the moment space instead of rejected,
// i.e. D33 := 0, which is what the shaders' pivot floor does with it.
double solve(glm::dvec4 bIn, double zfIn, double alphaIn, bool project) {
    const R a = alphaIn, zf = zfIn;
    const R b1 = (1 - a) * R(bIn.x) + a / 2, b2 = (1 - a) * R(bIn.y) + a / 2;
    const R b3 = (1 - a) * R(bIn.z) + a / 2, b4 = (1 - a) * R(bIn.w) + a / 2;
    const double nan = std::numeric_limits<double>::quiet_NaN();

    const R variance = b2 - b1 * b1;
    if (variance < -1e-15L) return nan;
    if (variance <= 1e-15L) return zf > b1 ? 1.0 : 0.0;  // one point mass at b1

    // Adjugate of B = [[1,b1,b2],[b1,b2,b3],[b2,b3,b4]] (symmetric).
    const R A11 = b2 * b4 - b3 * b3, A12 = b2 * b3 - b1 * b4, A13 = b1 * b3 - b2 * b2;
    const R A22 = b4 - b2 * b2, A23 = b1 * b2 - b3, A33 = variance;
    const R det = A11 + b1 * A12 + b2 * A13;
    if (det < -1e-17L && !project) return nan;
    if (det <= 1e-17L) {
        // Rank 2: two support points, the roots of the null vector's polynomial (the
        // adjugate's largest column). Unique distribution: G is its CDF strictly below zf.
        const R n[3][3] = {{A11, A12, A13}, {A12, A22, A23}, {A13, A23, A33}};
        int k = 0;
        for (int i = 1; i < 3; ++i)
            if (std::fabs(n[i][i]) > std::fabs(n[k][k])) k = i;
        R za, zb;
        roots(n[k][0], n[k][1], n[k][2], za, zb);
        const R wa = (b1 - zb) / (za - zb);
        return double(std::clamp<R>((za < zf ? wa : 0) + (zb < zf ? 1 - wa : 0), 0, 1));
    }

    const R c1 = A11 + A12 * zf + A13 * zf * zf;
    const R c2 = A12 + A22 * zf + A23 * zf * zf;
    const R c3 = A13 + A23 * zf + A33 * zf * zf;
    const R scale = std::max({std::fabs(c1), std::fabs(c2), std::fabs(c3)});
    R G;
    if (std::fabs(c3) <= 1e-30L * scale) {
        // Linear: the third point went to infinity with weight 0; support {zf, r}.
        const R r = -c1 / c2;
        G = r < zf ? (b1 - zf) / (r - zf) : 0;
    } else {
        R z2, z3;
        roots(c1, c2, c3, z2, z3);
        if (zf <= z2) G = 0;
        else if (zf <= z3) G = weight(z2, zf, z3, b1, b2);
        else G = 1 - weight(zf, z2, z3, b1, b2);
    }
    return double(std::clamp<R>(G, 0, 1));
}

}  // namespace

double exactMomentShadowIntensity(glm::dvec4 b, double zf, double alpha) {
    return solve(b, zf, alpha, false);
}

double msmFloatSensitivity(glm::vec4 b, float zf, double alpha) {
    // A backward-stable Cholesky of B' in float32 solves a system whose entries are off by
    // ~u·sqrt(B'ii·B'jj) (Higham, Accuracy and Stability, Thm. 10.3), not by u·|entry|: near
    // depth 0 the tiny moments are only known to about u times the larger ones. So b_k moves
    // by 32u·sqrt(B'ii·B'jj) at its Hankel position, with B' the biased matrix. 32: the
    // shader does about a dozen dependent roundings (bias, D22, L32, D33) before the last
    // pivot, each worth a few u at that scale; 8u proved too tight on nearly singular B'
    // (the sweep found D33 off by 1e-7 for a nearly single depth, G off by 7e-4).
    constexpr double u = 1.0 / (1 << 24);
    const glm::dvec4 bd(b);
    const glm::dvec4 bb = (1.0 - alpha) * glm::abs(bd) + alpha * 0.5;
    const double k = 32 * u;
    const double delta[4] = {k * std::sqrt(bb.y), k * std::max(bb.y, std::sqrt(bb.w)),
                             k * std::sqrt(bb.y * bb.w), k * bb.w};
    const double g0 = exactMomentShadowIntensity(bd, zf, alpha);
    double worst = 0.0;
    for (int pattern = 0; pattern < 18; ++pattern) {
        glm::dvec4 p = bd;
        double z = zf;
        if (pattern < 16) {
            for (int c = 0; c < 4; ++c) p[c] += ((pattern >> c) & 1 ? 1 : -1) * delta[c];
            z += (pattern % 3 == 0 ? 4 : -4) * u * std::abs(double(zf));
        } else {
            z += (pattern == 16 ? 4 : -4) * u * std::abs(double(zf));
        }
        // A perturbation that leaves the moment space lands where the float pivot floor
        // puts it: on the boundary (project = true).
        const double g = solve(p, z, alpha, true);
        if (std::isfinite(g) && std::isfinite(g0)) worst = std::max(worst, std::abs(g - g0));
    }
    return worst;
}

}  // namespace sl
