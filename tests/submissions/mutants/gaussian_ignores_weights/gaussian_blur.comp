// MUTANT: ignores uWeights: computes its own weights for sigma = r / 2, right only when the scene's sigma is r / 2
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
// T consecutive texels along the blur direction from one window of T + 2r texels, so every
// loaded texel serves T outputs. The radius is the compile-time constant SL_BLUR_RADIUS, so
// the loops unroll and the window lives in registers. Mesa unrolls a loop only up to 32
// iterations, so the window is loaded in four loops and the taps are summed in two (a single
// 34-iteration loop made r = 16 cost 4.2 copies instead of 1.9). A shared-memory tile, the
// classic GPU design, is slower here: llvmpipe emulates shared memory and barriers per lane.

layout(local_size_x = 16, local_size_y = 4) in;

// Its own normalised Gaussian weights for sigma = r / 2 (the handout's default), instead of
// the framework's uWeights.
float ownWeight(int k)
{
    float sigma = 0.5 * float(SL_BLUR_RADIUS);
    float sum = 1.0;
    for (int j = 1; j <= SL_BLUR_RADIUS; ++j) sum += 2.0 * exp(-float(j * j) / (2.0 * sigma * sigma));
    return exp(-float(k * k) / (2.0 * sigma * sigma)) / sum;
}

layout(binding = 0, rgba32f) uniform readonly  image2D uSource;
layout(binding = 1, rgba32f) uniform writeonly image2D uDestination;
layout(std430, binding = 0) readonly buffer GaussianWeights { float uWeights[]; };
uniform int   uRadius;     // == SL_BLUR_RADIUS
uniform ivec2 uDirection;  // (1, 0) or (0, 1)
uniform ivec2 uImageSize;

#define R SL_BLUR_RADIUS
// Texels written per invocation: 3 while the window stays small, 2 for wide kernels, where a
// larger window costs more in registers than it saves in loads (measured, r = 4..16).
#define T (R <= 8 ? 3 : 2)
uniform int uTexelsPerInvocation = T;  // read back by the framework to size the dispatch
#define N (T + 2 * R)                   // window length

vec4 window[N];

// Loads window[begin .. end): source texels first - R + i along the line, clamped to the edge
// (repeating the border texel is the contract's edge rule).
void loadWindow(int begin, int end, ivec2 first, ivec2 last)
{
    for (int i = begin; i < end; ++i)
        window[i] = imageLoad(uSource, clamp(first + (i - R) * uDirection, ivec2(0), last));
}

void main()
{
    ivec2 g = ivec2(gl_GlobalInvocationID.xy);
    ivec2 first = g + g * uDirection * (T - 1);  // stretched by T along the blur direction
    ivec2 last = uImageSize - 1;

    loadWindow(0, N / 4, first, last);
    loadWindow(N / 4, N / 2, first, last);
    loadWindow(N / 2, 3 * N / 4, first, last);
    loadWindow(3 * N / 4, N, first, last);

    for (int j = 0; j < T; ++j) {
        ivec2 p = first + j * uDirection;
        // Symmetric kernel: pair the taps at ±k, r + 1 multiplies instead of 2r + 1.
        vec4 sum = ownWeight(0) * window[j + R];
        for (int k = 1; k <= R / 2; ++k)
            sum += ownWeight(k) * (window[j + R - k] + window[j + R + k]);
        for (int k = R / 2 + 1; k <= R; ++k)
            sum += ownWeight(k) * (window[j + R - k] + window[j + R + k]);
        // A guard rather than `break`: a loop exit stops Mesa from unrolling this loop.
        if (all(lessThanEqual(p, last)))
            imageStore(uDestination, p, sum);
    }
}
