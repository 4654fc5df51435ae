// esm_probe.comp: techniques/esm.glsl's G on given (filtered value m, receiver depth z_f,
// exponent c), as the lighting pass compiles it (tests/test_technique_esm.cpp).
#define SL_PROBE
#include "techniques/esm.glsl"

layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Inputs { vec4 inputs[]; };  // (m, z_f, c, -)
layout(std430, binding = 2) writeonly buffer Outputs { float outputs[]; };
uniform int uCount;

void main() {
    int i = int(gl_GlobalInvocationID.x);
    if (i >= uCount) return;
    vec4 a = inputs[i];
    outputs[i] = esmShadowIntensity(a.x, a.y, esmExponent(a.z));
}
