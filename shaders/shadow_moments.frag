// shadow_moments.frag: the shadow pass's fragment shader. It measures the fragment's distance
// from the light and stores the moments of its relative depth (student: moments.glsl).
#include "moments.glsl"

in vec3 vWorldPosition;
in vec3 vWorldNormal;

uniform vec3 uLightEye;      // lightDepth = dot(p - eye, forward), world units
uniform vec3 uLightForward;
uniform vec2 uDepthRange;    // (near, far) for relativeDepth

layout(location = 0) out vec4 outMoments;

void main() {
    float lightDepth = dot(vWorldPosition - uLightEye, uLightForward);
    outMoments = computeMoments(relativeDepth(lightDepth, uDepthRange));
}
