// techniques/filter_gaussian.comp: one separable Gaussian pass for the framework's techniques,
// in the map's own format (SL_MAP_FORMAT: r32f, rg32f, rgba32f or rgba16). The weights are the
// buffer gaussian_blur.comp gets (w0 + 2 Σ w_k = 1) and the edge texel repeats (clamp). The sums
// run in the reference's order, so a technique's filtered map equals msm4's bit for bit for the
// same radius and σ (tests/test_numerics_gaussian.cpp).
//
// The design is the reference's register tile (docs/performance.md, "What a Gaussian design
// costs"): each invocation writes T = 8 consecutive texels along the blur direction from one
// window of T + 2r texels (3 loads per output at r = 8 instead of 17), the radius is a
// compile-time constant SL_BLUR_RADIUS so every loop unrolls and the window stays in
// registers, and 64×1 work groups put llvmpipe's SIMD lanes on consecutive texels of a row in
// both passes. The framework dispatches ceil(W / (64·Tx)) × ceil(H / Ty) groups (Tx = T for the
// x pass, Ty = T for the y pass), reading uTexelsPerInvocation back. About 4× faster than the
// plain loop over uRadius it replaces.
layout(local_size_x = 64, local_size_y = 1) in;
layout(binding = 0, SL_MAP_FORMAT) uniform readonly image2D uSource;
layout(binding = 1, SL_MAP_FORMAT) uniform writeonly image2D uDestination;
layout(std430, binding = 0) readonly buffer GaussianWeights { float uWeights[]; };
uniform int uRadius;  // == SL_BLUR_RADIUS
uniform ivec2 uDirection;
uniform ivec2 uImageSize;

#ifndef SL_BLUR_RADIUS
// Only for a compile without a radius (a program cache warmed without one); the passes always
// compile with SL_BLUR_RADIUS = uRadius.
#define SL_BLUR_RADIUS 1
#endif
#define R SL_BLUR_RADIUS
#define T 8  // main() writes outputs 0..7: change both together
uniform int uTexelsPerInvocation = T;
#define N (T + 2 * R)  // window length

vec4 window[N];
float weight[R + 1];

// window[begin .. end) = source texels first - R + i along the line, clamped to the edge.
void loadWindow(int begin, int end, ivec2 first, ivec2 last) {
    for (int i = begin; i < end; ++i)
        window[i] = imageLoad(uSource, clamp(first + (i - R) * uDirection, ivec2(0), last));
}

void loadWeights(int begin, int end) {
    for (int k = begin; k < end; ++k) weight[k] = uWeights[k];
}

// Output j: the taps at ±k paired, k = 1..R in order (the reference's summation order).
void writeOutput(int j, ivec2 first, ivec2 last) {
    vec4 sum = weight[0] * window[j + R];
    for (int k = 1; k <= R / 2; ++k)
        sum += weight[k] * (window[j + R - k] + window[j + R + k]);
    for (int k = R / 2 + 1; k <= R; ++k)
        sum += weight[k] * (window[j + R - k] + window[j + R + k]);
    ivec2 p = first + j * uDirection;
    if (all(lessThanEqual(p, last))) imageStore(uDestination, p, sum);
}

// The y pass walks the groups in bands of 4 (256 texels wide), as the reference does
// (reference/gaussian_blur.comp, bandedGroup): the group below, which reads the same rows
// again, runs while they are still in L2, whatever the image width. Float division: llvmpipe
// divides vector integers lane by lane.
ivec2 bandedGroup() {
    ivec2 groups = ivec2(gl_NumWorkGroups.xy);
    int band = uDirection.y == 1 ? 4 : groups.x;  // x pass: one band, the identity
    int linear = int(gl_WorkGroupID.x) + int(gl_WorkGroupID.y) * groups.x;
    int perBand = min(band, groups.x) * groups.y;
    int b = int((float(linear) + 0.5) / float(perBand));
    int inBand = linear - b * perBand;
    int width = min(band, groups.x - b * band);  // the last band may be narrower
    int row = int((float(inBand) + 0.5) / float(width));
    return ivec2(b * band + inBand - row * width, row);
}

void main() {
    ivec2 g = bandedGroup() * ivec2(gl_WorkGroupSize.xy) + ivec2(gl_LocalInvocationID.xy);
    ivec2 first = g + g * uDirection * (T - 1);  // stretched by T along the blur direction
    ivec2 last = uImageSize - 1;

    // Short flat loops, each unrolled on its own (Mesa unrolls innermost loops of <= 32 trips).
    loadWeights(0, R / 2 + 1);
    loadWeights(R / 2 + 1, R + 1);
    loadWindow(0, N / 8, first, last);
    loadWindow(N / 8, 2 * N / 8, first, last);
    loadWindow(2 * N / 8, 3 * N / 8, first, last);
    loadWindow(3 * N / 8, 4 * N / 8, first, last);
    loadWindow(4 * N / 8, 5 * N / 8, first, last);
    loadWindow(5 * N / 8, 6 * N / 8, first, last);
    loadWindow(6 * N / 8, 7 * N / 8, first, last);
    loadWindow(7 * N / 8, N, first, last);

    writeOutput(0, first, last);
    writeOutput(1, first, last);
    writeOutput(2, first, last);
    writeOutput(3, first, last);
    writeOutput(4, first, last);
    writeOutput(5, first, last);
    writeOutput(6, first, last);
    writeOutput(7, first, last);
}
