// probe_moments.comp: evaluates relativeDepth and computeMoments on arbitrary inputs, one
// invocation per case, with exactly the GLSL the shadow pass compiles.
layout(local_size_x = 64) in;

#include "moments.glsl"

layout(std430, binding = 0) readonly buffer ProbeDepths { vec4 probeInputs[]; };  // (lightDepth, near, far, -)
layout(std430, binding = 2) writeonly buffer ProbeResults { vec4 probeResults[]; };
uniform int uCount;

void main() {
    int i = int(gl_GlobalInvocationID.x);
    if (i >= uCount) return;
    vec4 in_ = probeInputs[i];
    probeResults[i] = computeMoments(relativeDepth(in_.x, in_.yz));
}
