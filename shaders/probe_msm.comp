// probe_msm.comp: evaluates momentShadowIntensity on arbitrary inputs, one invocation per
// case, with exactly the GLSL the lighting pass compiles (shadowlab probe; tests; grader).
layout(local_size_x = 64) in;

uniform float uMomentBias;
#include "msm.glsl"

layout(std430, binding = 0) readonly buffer ProbeMoments { vec4 probeMoments[]; };
layout(std430, binding = 1) readonly buffer ProbeDepths { float probeDepths[]; };
layout(std430, binding = 2) writeonly buffer ProbeResults { float probeResults[]; };
uniform int uCount;

void main() {
    int i = int(gl_GlobalInvocationID.x);
    if (i >= uCount) return;
    probeResults[i] = momentShadowIntensity(probeMoments[i], probeDepths[i]);
}
