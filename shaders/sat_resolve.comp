// sat_resolve.comp: evaluates the student's satBoxAverage at every texel centre, turning a
// summed-area table back into a filtered moment map (an output for inspection and grading;
// lighting reads the table directly).
layout(local_size_x = 8, local_size_y = 8) in;

#include "sat_lookup.glsl"

uniform sampler2D uSat;
layout(binding = 1, rgba32f) uniform writeonly image2D uDestination;
uniform float uSatKernel;  // box size in texels

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(uDestination);  // the map's (the table is twice as wide)
    if (any(greaterThanEqual(p, size))) return;
    imageStore(uDestination, p, satBoxAverage(uSat, vec2(p) + 0.5, vec2(uSatKernel)));
}
