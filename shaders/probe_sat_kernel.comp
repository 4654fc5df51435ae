// probe_sat_kernel.comp: evaluates satKernelTexels on arbitrary receivers over a summed-area
// table that the solution's own sat.comp built, one invocation per case, with exactly the
// GLSL the lighting pass compiles (tests; the grader's sat stage grades it in the lighting).
layout(local_size_x = 64) in;

#include "sat_lookup.glsl"

uniform sampler2D uSat;
// Per case, three vec4: (cx, cy, searchTexels, zr), (near, far, lightTexels, perspective),
// (smallest box, largest box, -, -).
layout(std430, binding = 0) readonly buffer ProbeCases { vec4 probeCases[]; };
layout(std430, binding = 2) writeonly buffer ProbeResults { float probeResults[]; };
uniform int uCount;

void main() {
    int i = int(gl_GlobalInvocationID.x);
    if (i >= uCount) return;
    vec4 a = probeCases[3 * i], b = probeCases[3 * i + 1], c = probeCases[3 * i + 2];
    probeResults[i] = satKernelTexels(uSat, a.xy, a.z, a.w, b.xy, b.z, b.w != 0.0, c.xy);
}
