// moments.glsl: relative depth and the four moments stored in the shadow map.
// Stage contract: docs/stage_contract.md (the part that concerns this file is repeated here).
//
// Used by the shadow pass (shaders/techniques/store.frag) for every texel of the shadow map:
//     moments = computeMoments(relativeDepth(lightDepth, depthRange));
// and by the lighting pass for the fragment it shades (relativeDepth only).
// Do not write a #version line: the framework prepends `#version 450 core`.
//
// float relativeDepth(float lightDepth, vec2 depthRange)
//   lightDepth  distance of the point from the light, in world units, measured along the
//               light's forward axis (spot light: view-space -z; directional light: along its
//               direction from the plane through the scene's bounds).
//   depthRange  (near, far) in the same units, from the scene. far > near.
//   returns     (lightDepth - near) / (far - near), clamped to [0, 1]. The grader checks the
//               clamp on light depths outside [near, far] too (`shadowlab probe moments
//               --generate depth-ladder` writes them, with the expected moments).
//
// vec4 computeMoments(float z)
//   z           a relative depth in [0, 1].
//   returns     the moments (b1, b2, b3, b4) = (z, z², z³, z⁴) (Peters & Klein 2015), stored
//               in the RGBA32F shadow map.
//
// Stub value: until implemented, both functions return -1 (every channel), which the
// framework reports as "not implemented yet" and previews in magenta. A correct solution
// never returns a negative value.

float relativeDepth(float lightDepth, vec2 depthRange)
{
    // TODO: not implemented yet: relativeDepth
    // Map lightDepth linearly so that near -> 0 and far -> 1, and clamp the result to [0, 1]
    // (points in front of near or behind far must still give a valid depth).
    return -1.0;
}

vec4 computeMoments(float z)
{
    // TODO: not implemented yet: computeMoments
    // Return the first four powers of z. Think about how to compute them with few
    // multiplications (pow() is slower and less exact than multiplying).
    return vec4(-1.0);
}
