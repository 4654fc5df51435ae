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
// a negative value. (This stub writes one texel per invocation: T = 1.)

// Work groups of 32 x 2, kept from the reference's measurements (docs/performance.md): llvmpipe
// runs 8 consecutive invocations along x as the lanes of one SIMD vector, so in both passes
// the lanes read neighbouring texels of a row (whole 64-byte cache lines) and the next vectors
// continue along it. 8 x 8 groups walk down columns instead (a new line 16 KiB away per load):
// 3.4-4.4 copy passes for the y pass at r = 8 against 1.3-1.6 in rows. Keep a group's span
// along x (local_size_x · T in the x pass) within the map's width: `bench` times 256² maps,
// and the lanes of a group past the map's edge only test their bounds.
layout(local_size_x = 32, local_size_y = 2, local_size_z = 1) in;

layout(binding = 0, rgba32f) uniform readonly  image2D uSource;
layout(binding = 1, rgba32f) uniform writeonly image2D uDestination;
layout(std430, binding = 0) readonly buffer GaussianWeights { float uWeights[]; };
uniform int   uRadius;     // r == SL_BLUR_RADIUS
uniform ivec2 uDirection;  // (1, 0): blur along rows (x); (0, 1): along columns (y)
uniform ivec2 uImageSize;  // width, height of both images

void main()
{
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);

    // TODO: not implemented yet: gaussian_blur.comp (one separable Gaussian pass)
    //  - Sum the 2r + 1 taps source(p + k·uDirection), k = -r .. r, each clamped to the image
    //    (clamp(..., ivec2(0), uImageSize - 1)), weighted by uWeights[abs(k)].
    //  - The kernel is symmetric: pair the taps at ±k, w_k · (a + b), to halve the multiplies.
    //  - Loop up to SL_BLUR_RADIUS (a constant) rather than uRadius, so the compiler can
    //    unroll it.
    //  - Faster (optional): write T > 1 texels per invocation from one window of T + 2r
    //    loaded texels, so that each loaded texel serves several outputs; declare
    //    uTexelsPerInvocation and follow the mapping above.
    //  - Measure your pass against the plain copy pass: `shadowlab bench` (see the handout).

    // Stub: this invocation's texel gets the stub value -1.
    if (any(greaterThanEqual(p, uImageSize)))
        return;
    imageStore(uDestination, p, vec4(-1.0));
}
