// MUTANT: relative depth divides by far instead of (far - near)
// moments.glsl: relative depth and the four moments stored in the shadow map.
// Reference solution. Stage contract: docs/stage_contract.md.
//
// Used by the shadow pass (shaders/techniques/store.frag) for every texel of the shadow
// map, and by the lighting pass for the fragment it shades (relativeDepth only).
// Moment Shadow Mapping, Peters & Klein (I3D 2015): a texel stores the power moments
// b = (b1, b2, b3, b4) = (z, z^2, z^3, z^4) of the depth z of the surface it sees. These
// are linear in the depth distribution, so filtering the texels (Gaussian, box) gives the
// moments of the filtered depth distribution, which msm.glsl turns into a shadow.

// Relative depth z in [0, 1] of a point at distance lightDepth from the light (along the
// light's forward axis), with depthRange = (near, far) in the same units.
// Clamping matters: points outside [near, far] (receivers behind the last caster, the
// cleared background) would otherwise produce moments outside the moment space of [0, 1],
// which the bias in msm.glsl is calibrated for. The framework guarantees far > near.
float relativeDepth(float lightDepth, vec2 depthRange)
{
    return clamp((lightDepth - depthRange.x) / depthRange.y, 0.0, 1.0);
}

// The power moments b = (z, z^2, z^3, z^4) of a point mass at depth z (before any bias;
// msm.glsl biases after filtering). The powers are built from z^2 with two multiplies
// rather than pow(): exact enough, cheaper, and consistent (b3 = b2 * b1, b4 = b2 * b2), so
// the Hankel matrix of a single depth stays as close to singular-but-valid as float allows.
vec4 computeMoments(float z)
{
    float z2 = z * z;
    return vec4(z, z2, z2 * z, z2 * z2);
}
