// probe_sat_lookup.comp: evaluates satBoxAverage on arbitrary boxes of a summed-area table
// that the solution's own sat.comp built, one invocation per box, with exactly the GLSL the
// lighting pass compiles (shadowlab probe sat-lookup; tests; grader).
layout(local_size_x = 64) in;

#include "sat_lookup.glsl"

uniform sampler2D uSat;
layout(std430, binding = 0) readonly buffer ProbeBoxes { vec4 probeBoxes[]; };  // (cx, cy, w, h)
layout(std430, binding = 2) writeonly buffer ProbeResults { vec4 probeResults[]; };
uniform int uCount;

void main() {
    int i = int(gl_GlobalInvocationID.x);
    if (i >= uCount) return;
    vec4 box = probeBoxes[i];
    probeResults[i] = satBoxAverage(uSat, box.xy, box.zw);
}
