// msm_exact: the exact Hamburger 4MSM value, in long double, by a route independent of the
// shaders' LDLᵀ factorisation (adjugate of the Hankel matrix, no pivot floors). It gives the
// hard-case catalogue its expected values and the property sweep its reference.
#pragma once

#include <glm/glm.hpp>

namespace sl {

// The smallest weight in front of zf over all distributions with the biased moments
// (1, b'), b' = (1 − α)·b + α·(0.5, 0.5, 0.5, 0.5) (Peters & Klein 2015). Singular cases
// (support of one or two points, e.g. depth only at 0 and 1) are solved as the unique
// distribution they are. NaN when even b' is not a valid moment vector.
double exactMomentShadowIntensity(glm::dvec4 b, double zf, double alpha);

// How far exact G moves when the inputs move by a backward-stable float32 Cholesky's error
// (b_k by ±32u·sqrt(B'ii·B'jj) at its Hankel position, zf by ±4u·|zf|; u = 2^-24; 18 sign
// patterns): the error a float32 evaluation may make on these inputs, on top of a rounding.
double msmFloatSensitivity(glm::vec4 b, float zf, double alpha);

}  // namespace sl
