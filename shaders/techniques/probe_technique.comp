// techniques/probe_technique.comp: evaluates the technique files' functions on arbitrary
// inputs, with exactly the GLSL the lighting pass compiles (tests/test_technique_mirror.cpp
// compares them with double-precision CPU mirrors), on the solution's msm.glsl. Case i reads inputs[3i .. 3i+2] = (a, b, c)
// and writes outputs[i]; uFunction picks the function (see main).
#define SL_PROBE
#define SL_STAGE_MSM
uniform float uMomentBias;  // msm.glsl's α
#include "msm.glsl"
#include "techniques/common.glsl"
#include "techniques/evsm_common.glsl"
#include "techniques/msm_hamburger.glsl"
#include "techniques/hard.glsl"
#include "techniques/second_depth.glsl"
#include "techniques/vsm.glsl"
#include "techniques/evsm2.glsl"
#include "techniques/evsm4.glsl"
#include "techniques/csm.glsl"
#include "techniques/msm4_hausdorff.glsl"
#include "techniques/msm4_16bit.glsl"

layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Inputs { vec4 inputs[]; };
layout(std430, binding = 2) writeonly buffer Outputs { vec4 outputs[]; };
uniform int uCount;
uniform int uFunction;

void main() {
    int i = int(gl_GlobalInvocationID.x);
    if (i >= uCount) return;
    vec4 a = inputs[3 * i], b = inputs[3 * i + 1], c = inputs[3 * i + 2];
    vec4 r = vec4(0.0);
    switch (uFunction) {
        case 0: r.x = hardShadowTest(a.x, b.x, b.y); break;
        case 1: r.x = secondDepthShadowTest(a.x, a.y, b.x); break;
        case 2: r.x = vsmShadowIntensity(a.xy, b.x, b.y, b.z); break;
        case 3: r.x = evsm2ShadowIntensity(a.xy, b.x, b.y, b.z, b.w); break;
        case 4: r.x = evsm4ShadowIntensity(a, b.x, b.y, b.z, c.x, c.y); break;
        case 5: {
            vec4 layers[SL_CSM_LAYERS];
            layers[0] = a;
            layers[1] = c;
            r.x = csmShadowIntensity(layers, b.x, b.y, b.z, b.w);
            break;
        }
        case 6: r.x = msm4HausdorffShadowIntensity(a, b.x, b.y); break;
        case 7: r.x = msm4QuantizedShadowIntensity(a, b.x, b.y); break;
        case 8: r.xy = msmBlockers(a, b.x, b.y); break;
        case 9: r = msmQuantize16(a); break;
        case 10: r.x = momentShadowIntensity(a, b.x); break;  // α = uMomentBias
    }
    outputs[i] = r;
}
