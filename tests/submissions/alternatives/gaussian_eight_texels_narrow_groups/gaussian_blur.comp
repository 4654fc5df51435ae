// ALTERNATIVE: written from the student kit alone: T = 8 texels an invocation, 32x1 groups, one clamped window of 8 + 2r loads, the outputs as 8 explicit calls
// gaussian_blur.comp: one pass of a separable Gaussian blur of the moment map.
// Stage contract: docs/stage_contract.md (the part that concerns this file is repeated here).
//
// Filter pass, compute shader. Do not write a #version line: the framework prepends
// `#version 450 core` and `#define SL_BLUR_RADIUS r`. Dispatched twice: along x, then y.
//
// Inputs and outputs:
//   uSource       (image binding 0, RGBA32F, read only)   moments (b1, b2, b3, b4)
//   uDestination  (image binding 1, RGBA32F, write only)  same size as uSource
//   uWeights      (SSBO binding 0) one-sided normalised Gaussian weights w_0 .. w_r:
//                 w0 + 2·(w1 + … + wr) = 1, w_k ∝ exp(−k² / 2σ²)
//   uRadius       r: the kernel has 2r + 1 taps. Also the compile-time constant
//                 SL_BLUR_RADIUS (one program per radius), so tap loops can be unrolled.
//   uDirection    (1, 0): blur along rows (x); (0, 1): along columns (y)
//   uImageSize    width, height of both images
// Output texel p = Σ_{k=-r..r} w_|k| · source(clamp(p + k·uDirection)): the edge texel is
// repeated (clamp to edge).
//
// Invocation mapping (image space): with T = uTexelsPerInvocation (1 unless your shader
// declares that uniform with an initializer, e.g. `uniform int uTexelsPerInvocation = 2;`,
// which the framework reads back from the driver: use it in your code, since an unused uniform
// is dropped and reads as 1), invocation g = gl_GlobalInvocationID.xy writes the T
// texels p0 + j·uDirection, j = 0 … T−1, where p0 = g + g·uDirection·(T − 1). The framework
// dispatches ceil(W / (local_size_x·Tx)) × ceil(H / (local_size_y·Ty)) work groups, Tx = T for
// the x pass and Ty = T for the y pass (1 otherwise), reading the local size you declare.
// Invocations and texels outside the image must not write.
//
// Stub value: until implemented, the pass writes -1 to every texel, which the framework
// reports as "not implemented yet" and previews in magenta. A correct solution never writes
// a negative value. This solution writes T = 8 texels per invocation (below).

// Work groups of 32 x 1 (the stub had 64 x 1): llvmpipe runs 8 consecutive invocations along
// x as the lanes of one SIMD vector, so in both passes the lanes read along a row. With 8
// texels per invocation a 64-wide group covers 512 texels of the x pass, so on a 256-texel map
// half of every group idled; 32 x 1 keeps them busy (measured with `./kit bench --exact`:
// r = 8 x pass 2.08 -> 1.29 copies, r = 16 2.94 -> 1.77) and costs the same at 1024².
layout(local_size_x = 32, local_size_y = 1, local_size_z = 1) in;

layout(binding = 0, rgba32f) uniform readonly  image2D uSource;
layout(binding = 1, rgba32f) uniform writeonly image2D uDestination;
layout(std430, binding = 0) readonly buffer GaussianWeights { float uWeights[]; };
uniform int   uRadius;     // r == SL_BLUR_RADIUS
uniform ivec2 uDirection;  // (1, 0): blur along rows (x); (0, 1): along columns (y)
uniform ivec2 uImageSize;  // width, height of both images

// T texels per invocation from one window of T + 2r texels (docs/performance.md: 8 is the most
// that stays in registers). Every loop has a constant trip count, and the T outputs are T
// calls of one function (not a loop over the outputs), so everything unrolls and the window
// stays in registers.
#define SL_T 8
uniform int uTexelsPerInvocation = SL_T;

const int R = SL_BLUR_RADIUS;
vec4  gWindow[SL_T + 2 * R];   // gWindow[i] = source(p0 + (i - R)·uDirection), clamped
float gWeight[R + 1];

vec4 blurOutput(int j)
{
    // Output p0 + j·uDirection sits at window index j + R.
    vec4 sum = gWeight[0] * gWindow[j + R];
    for (int k = 1; k <= R; ++k)
        sum += gWeight[k] * (gWindow[j + R - k] + gWindow[j + R + k]);
    return sum;
}

void storeOutput(ivec2 p0, int j, vec4 value)
{
    ivec2 p = p0 + j * uDirection;
    if (all(lessThan(p, uImageSize)))
        imageStore(uDestination, p, value);
}

void main()
{
    ivec2 g  = ivec2(gl_GlobalInvocationID.xy);
    ivec2 p0 = g + g * uDirection * (uTexelsPerInvocation - 1);
    if (any(greaterThanEqual(p0, uImageSize)))
        return;

    ivec2 hi = uImageSize - 1;
    for (int k = 0; k <= R; ++k)
        gWeight[k] = uWeights[k];

    // The window in three flat loops (each short enough to unroll): left apron, centre, right apron.
    for (int i = 0; i < R; ++i)
        gWindow[i] = imageLoad(uSource, clamp(p0 + (i - R) * uDirection, ivec2(0), hi));
    for (int i = 0; i < SL_T; ++i)
        gWindow[R + i] = imageLoad(uSource, clamp(p0 + i * uDirection, ivec2(0), hi));
    for (int i = 0; i < R; ++i)
        gWindow[R + SL_T + i] = imageLoad(uSource, clamp(p0 + (SL_T + i) * uDirection, ivec2(0), hi));

    storeOutput(p0, 0, blurOutput(0));
    storeOutput(p0, 1, blurOutput(1));
    storeOutput(p0, 2, blurOutput(2));
    storeOutput(p0, 3, blurOutput(3));
    storeOutput(p0, 4, blurOutput(4));
    storeOutput(p0, 5, blurOutput(5));
    storeOutput(p0, 6, blurOutput(6));
    storeOutput(p0, 7, blurOutput(7));
}
