// MUTANT: wrong edge handling: taps outside the image count as zero instead of the edge texel
// gaussian_blur.comp — one pass of the separable Gaussian filter of the moment map
// (reference solution). The framework runs it along x, then along y: the 2D Gaussian is the
// product of two 1D ones, so 2·(2r+1) taps per texel instead of (2r+1)².
//
// Interface (docs/stage_contract.md): uSource -> uDestination, RGBA32F moments b = (b1..b4);
// uWeights[0..r] one-sided normalised weights, w0 + 2·Σ w_k = 1; clamp to edge.
// Filtering moments is linear, so blurring b is exactly the moments of the blurred depth
// distribution, which is what makes the shadow soft (Peters & Klein 2015, section 3).
//
// Design, measured on llvmpipe (docs/performance.md): a register tile. Each invocation writes
// T = 2 consecutive texels along the blur direction from one window of T + 2r texels, so every
// loaded texel serves two outputs. The radius is the compile-time constant SL_BLUR_RADIUS, so
// the loops unroll and the window lives in registers. A shared-memory tile, the classic GPU
// design, is slower here: llvmpipe emulates shared memory and barriers per SIMD lane.

layout(local_size_x = 16, local_size_y = 4) in;

layout(binding = 0, rgba32f) uniform readonly  image2D uSource;
layout(binding = 1, rgba32f) uniform writeonly image2D uDestination;
layout(std430, binding = 0) readonly buffer GaussianWeights { float uWeights[]; };
uniform int   uRadius;     // == SL_BLUR_RADIUS
uniform ivec2 uDirection;  // (1, 0) or (0, 1)
uniform ivec2 uImageSize;

#define T 2                            // texels written per invocation
uniform int uTexelsPerInvocation = T;  // read back by the framework to size the dispatch

#define R SL_BLUR_RADIUS

void main()
{
    ivec2 g = ivec2(gl_GlobalInvocationID.xy);
    ivec2 first = g + g * uDirection * (T - 1);  // stretched by T along the blur direction
    ivec2 last = uImageSize - 1;

    // The window: source texels first - R .. first + T - 1 + R along the line, clamped to
    // the edge (repeating the border texel is the contract's edge rule).
    vec4 window[T + 2 * R];
    for (int i = 0; i < T + 2 * R; ++i)
    {
        ivec2 q = first + (i - R) * uDirection;
        window[i] = (any(lessThan(q, ivec2(0))) || any(greaterThan(q, last))) ? vec4(0.0)
                                                                     : imageLoad(uSource, q);
    }

    for (int j = 0; j < T; ++j) {
        ivec2 p = first + j * uDirection;
        if (any(greaterThan(p, last))) break;
        // Symmetric kernel: pair the taps at ±k, r + 1 multiplies instead of 2r + 1.
        vec4 sum = uWeights[0] * window[j + R];
        for (int k = 1; k <= R; ++k)
            sum += uWeights[k] * (window[j + R - k] + window[j + R + k]);
        imageStore(uDestination, p, sum);
    }
}
