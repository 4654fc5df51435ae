// present.frag: shows one image of a render in the viewer window. Linear colour is
// sRGB-encoded; the stub value -1 and NaN are magenta, as in the PNG previews.
in vec2 vUv;
uniform sampler2D uImage;
uniform int uChannels;   // 1: grey, 3 or 4: colour (the first three channels)
uniform int uEncodeSrgb;
layout(location = 0) out vec4 outColor;

vec3 srgb(vec3 c) {
    c = clamp(c, 0.0, 1.0);
    return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(0.0031308, c));
}

void main() {
    vec4 v = texture(uImage, vUv);
    vec3 c = uChannels == 1 ? v.rrr : v.rgb;
    bool broken = any(isnan(c)) || (uChannels == 1 ? v.r == -1.0 : all(equal(v, vec4(-1.0))));
    outColor = vec4(broken ? vec3(1.0, 0.0, 1.0) : (uEncodeSrgb != 0 ? srgb(c) : clamp(c, 0.0, 1.0)), 1.0);
}
