// probe_moments.comp: evaluates relativeDepth and computeMoments on arbitrary inputs, one
// invocation per case, with exactly the GLSL the shadow pass compiles. An input whose w is not
// 0 asks for relativeDepth alone (in every channel), so that either function is probed alone.
layout(local_size_x = 64) in;

#include "moments.glsl"

layout(std430, binding = 0) readonly buffer ProbeDepths { vec4 probeInputs[]; };  // (lightDepth, near, far, alone)
layout(std430, binding = 2) writeonly buffer ProbeResults { vec4 probeResults[]; };
uniform int uCount;

void main() {
    int i = int(gl_GlobalInvocationID.x);
    if (i >= uCount) return;
    vec4 in_ = probeInputs[i];
    float z = relativeDepth(in_.x, in_.yz);
    probeResults[i] = in_.w != 0.0 ? vec4(z) : computeMoments(z);
}
