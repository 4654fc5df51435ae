// pcf_bruteforce.comp: a brute-force GPU PCF for tests/test_truth_filtered.cpp. For each sample
// (uv, zf) it visits every texel of the kernel's support and adds the texel's weight where
// z < zf, in float: the Gaussian kernel as the moment filter's weights times the bilinear
// fetch's weights (clamp to edge), or the SAT's box with partial coverage (clipped).
layout(local_size_x = 64) in;

layout(std430, binding = 0) readonly buffer Samples { vec4 samples[]; };  // (u, v, zf, -)
layout(std430, binding = 1) readonly buffer Weights { float weights[]; };  // w[0..r]
layout(std430, binding = 2) writeonly buffer Result { float result[]; };
uniform sampler2D uDepth;  // R32F, texelFetch only
uniform int uCount;
uniform int uRadius;       // gaussian; -1: box
uniform float uBox;        // box width in texels

float zAt(int x, int y) { return texelFetch(uDepth, ivec2(x, y), 0).r; }

void main() {
    int i = int(gl_GlobalInvocationID.x);
    if (i >= uCount) return;
    vec4 s = samples[i];
    ivec2 n = textureSize(uDepth, 0);
    float g = 0.0;
    if (uRadius >= 0) {
        vec2 st = s.xy * vec2(n) - 0.5;
        ivec2 i0 = ivec2(floor(st));
        vec2 f = st - vec2(i0);
        for (int by = 0; by < 2; ++by)
            for (int bx = 0; bx < 2; ++bx) {
                float wb = (bx == 0 ? 1.0 - f.x : f.x) * (by == 0 ? 1.0 - f.y : f.y);
                ivec2 c = clamp(i0 + ivec2(bx, by), ivec2(0), n - 1);
                for (int b = -uRadius; b <= uRadius; ++b) {
                    float row = 0.0;
                    for (int a = -uRadius; a <= uRadius; ++a) {
                        ivec2 t = clamp(c + ivec2(a, b), ivec2(0), n - 1);
                        if (zAt(t.x, t.y) < s.z) row += weights[abs(a)];
                    }
                    g += wb * weights[abs(b)] * row;
                }
            }
    } else {
        vec2 c = s.xy * vec2(n);
        vec2 lo = clamp(c - 0.5 * uBox, vec2(0.0), vec2(n));
        vec2 hi = clamp(c + 0.5 * uBox, vec2(0.0), vec2(n));
        for (int y = int(floor(lo.y)); y < int(ceil(hi.y)); ++y) {
            float row = 0.0;
            float cy = min(hi.y, float(y + 1)) - max(lo.y, float(y));
            for (int x = int(floor(lo.x)); x < int(ceil(hi.x)); ++x) {
                float cx = min(hi.x, float(x + 1)) - max(lo.x, float(x));
                if (zAt(x, y) < s.z) row += cx;
            }
            g += cy * row;
        }
        g /= (hi.x - lo.x) * (hi.y - lo.y);
    }
    result[i] = g;
}
