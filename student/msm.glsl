// msm.glsl: shadow intensity from four filtered moments (Hamburger 4MSM).
// Stage contract: docs/stage_contract.md (the part that concerns this file is repeated here).
//
// Included by the lighting pass (shaders/lighting.frag), which shades with
//     colour = ambient + (1 - G) · (diffuse + specular).
// Do not write a #version line: the framework prepends `#version 450 core`.
//
// uniform float uMomentBias;
//   α, the moment bias. Declared by the framework *before* this file is included: use it,
//   do not declare it again. Default 3·10⁻⁵ (moments stored as float32); scenes may override.
//
// float momentShadowIntensity(vec4 b, float zf)
//   b        the filtered moments (b1, b2, b3, b4) of the shadow map texel (after the Gaussian
//            blur or the summed-area-table box filter): the power moments of the depth
//            distribution the filter kernel sees, depths relative in [0, 1].
//   zf       the fragment's relative depth (moments.glsl's relativeDepth), from which the
//            framework has already subtracted the scene's depth bias.
//   returns  the shadow intensity G in [0, 1]: 0 lit, 1 fully shadowed. It must never be NaN.
//
// Stub value: until implemented, the function returns -1, which the framework reports as
// "not implemented yet" and previews in magenta. A correct solution never returns a
// negative value.

float momentShadowIntensity(vec4 b, float zf)
{
    // TODO: not implemented yet: momentShadowIntensity (Hamburger 4MSM)
    // Follow Peters & Klein 2015, Algorithm 3:
    //  1. Bias the moments toward a fixed, harmless moment vector:
    //         b' = (1 - α) · b + α · (0.5, 0.5, 0.5, 0.5)
    //     (mix() does this). Why this vector, and why does it help? See the handout.
    //  2. The Hankel matrix of b' is
    //         B = | 1   b1  b2 |
    //             | b1  b2  b3 |
    //             | b2  b3  b4 |
    //     Solve B · c = (1, zf, zf²)ᵀ for c = (c1, c2, c3) with a Cholesky factorisation.
    //     The square-root-free form B = L · D · Lᵀ (L unit lower triangular, D diagonal) is
    //     the easiest: work out L and D on paper for this 3×3 matrix, then do a forward
    //     substitution, a division by D and a backward substitution.
    //  3. The two real roots z2 <= z3 of c1 + c2 · z + c3 · z² = 0 are, together with zf, the
    //     support of a three-point depth distribution with the same moments.
    //  4. G is the total weight of the support points in front of zf:
    //         zf <= z2        -> G = 0
    //         z2 < zf <= z3   -> G = weight of z2
    //         z3 < zf         -> G = 1 - weight of zf
    //     The weights follow from matching the moments 1, b1', b2' of that distribution
    //     (the formulas are in the paper).
    //  5. Robustness: float32 rounding can make pivots of D or the quadratic's discriminant
    //     slightly negative or zero, and c3 can be (almost) zero. Guard every division and
    //     square root, and clamp G to [0, 1].
    return -1.0;
}
