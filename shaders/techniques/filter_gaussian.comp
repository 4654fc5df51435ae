// techniques/filter_gaussian.comp: one separable Gaussian pass for the framework's techniques,
// in the map's own format (SL_MAP_FORMAT: r32f, rg32f, rgba32f or rgba16). The weights are the
// buffer gaussian_blur.comp gets (w0 + 2 Σ w_k = 1) and the edge texel repeats (clamp), so a
// technique's filtered map equals msm4's for the same radius and σ.
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0, SL_MAP_FORMAT) uniform readonly image2D uSource;
layout(binding = 1, SL_MAP_FORMAT) uniform writeonly image2D uDestination;
layout(std430, binding = 0) readonly buffer GaussianWeights { float uWeights[]; };
uniform int uRadius;
uniform ivec2 uDirection;
uniform ivec2 uImageSize;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, uImageSize))) return;
    vec4 sum = uWeights[0] * imageLoad(uSource, p);
    for (int k = 1; k <= uRadius; ++k) {
        vec4 a = imageLoad(uSource, clamp(p + k * uDirection, ivec2(0), uImageSize - 1));
        vec4 b = imageLoad(uSource, clamp(p - k * uDirection, ivec2(0), uImageSize - 1));
        sum += uWeights[k] * (a + b);
    }
    imageStore(uDestination, p, sum);
}
