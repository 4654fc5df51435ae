// ALTERNATIVE: the plainest blur: one texel per invocation, 8×8 work groups, no shared memory
// and no register window; the 2r + 1 taps are read straight from the image and summed left
// to right, w_|k|·source(p + k·dir) for k = -r..r, instead of the reference's paired
// w_k·(a + b). Still correct: the same weighted sum in a different floating-point order
// (a sum of 2r + 1 non-negative terms whose weights add up to 1, so the two orders differ by
// at most a few units of float32 rounding), with the same clamp-to-edge rule, and a
// different work-group size and texels-per-invocation (T = 1: no uTexelsPerInvocation).

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(binding = 0, rgba32f) uniform readonly  image2D uSource;
layout(binding = 1, rgba32f) uniform writeonly image2D uDestination;
layout(std430, binding = 0) readonly buffer GaussianWeights { float uWeights[]; };
uniform int   uRadius;     // r: the kernel has 2r + 1 taps
uniform ivec2 uDirection;  // (1, 0): blur along rows (x); (0, 1): along columns (y)
uniform ivec2 uImageSize;  // width, height of both images

void main()
{
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    ivec2 last = uImageSize - 1;
    if (any(greaterThan(p, last)))
        return;
    vec4 sum = vec4(0.0);
    for (int k = -uRadius; k <= uRadius; ++k)
        sum += uWeights[abs(k)] * imageLoad(uSource, clamp(p + k * uDirection, ivec2(0), last));
    imageStore(uDestination, p, sum);
}
