// techniques/second_depth_peel.frag: the second shadow pass of `second-depth`: depth peeling.
// Fragments at or in front of the first depth (+ peelEpsilon) are discarded, so the depth test
// keeps the nearest surface behind the first: the second depth z2 (1 where there is none).
#include "moments.glsl"  // relativeDepth

in vec3 vWorldPosition;
in vec3 vWorldNormal;

uniform vec3 uLightEye;
uniform vec3 uLightForward;
uniform vec2 uDepthRange;
uniform sampler2D uFirstDepth;  // the first pass's map (R32F)
uniform float uPeelEpsilon;

layout(location = 0) out vec4 outSecond;

void main() {
    float z = relativeDepth(dot(vWorldPosition - uLightEye, uLightForward), uDepthRange);
    float z1 = texelFetch(uFirstDepth, ivec2(gl_FragCoord.xy), 0).r;
    if (z <= z1 + uPeelEpsilon) discard;
    outSecond = vec4(z, 0.0, 0.0, 0.0);
}
