// gaussian_blur.comp — one pass of the separable Gaussian filter of the moment map
// (reference solution). The framework runs it along x, then along y: the 2D Gaussian is the
// product of two 1D ones, so 2·(2r+1) taps per texel instead of (2r+1)².
//
// Interface (docs/stage_contract.md): uSource -> uDestination, RGBA32F moments b = (b1..b4);
// uWeights[0..r] one-sided normalised weights, w0 + 2·Σ w_k = 1; clamp to edge.
// Filtering moments is linear, so blurring b is exactly the moments of the blurred depth
// distribution, which is what makes the shadow soft (Peters & Klein 2015, section 3).
//
// Design, measured on llvmpipe (docs/performance.md, "What a Gaussian design costs"): a
// register tile. Each invocation writes T = 8 consecutive texels along the blur direction from
// one window of T + 2r texels, so every loaded texel serves up to 8 outputs (r = 8: 3 loads per
// output instead of 17). llvmpipe pays for every loop that Mesa does not unroll, and an array
// indexed in such a loop lives in memory, lane by lane: 4-6 copies instead of 1.3. Mesa unrolls
// a loop only when its trip count is at most 32 and its unrolled size is small, so every loop
// here is flat and short: the window loads in eight loops, the weights in two, and each output
// is its own call with two tap loops (a loop over the outputs around them grew too large to
// unroll at r = 16 and cost 6 copies). The weights are read into registers once, not per output
// (1.6 -> 1.25 copies at r = 8). A shared-memory tile, the classic GPU design, is slower here:
// llvmpipe emulates shared memory and barriers per lane.
//
// Work-group shape 32 x 2: llvmpipe runs 8 consecutive invocations (x fastest) as the lanes of
// one AVX2 vector (4 at 128 bits). In the y pass those lanes read 8 neighbouring texels of a
// row (two 64-byte cache lines) and consecutive vectors continue along the row, which the
// CPU's prefetcher follows; 8 x 8 groups walk down columns instead (one new 16 KiB-strided
// line per load): their y pass cost 3.5-4.3 copies at r = 8 on an AMD EPYC, 1.3-1.5 here.
// 32 wide, not 64: an x-pass group spans 32 x T = 256 texels of a row, and on a map narrower
// than a group's span the rest of the group only tests its bounds (64 x 1 on 256²: half of
// every x group idle, 1.87 copies in instructions at r = 8 against 1.11 now); 2 rows keep 64
// invocations a group. From 512² up the two shapes cost the same (30.48 / 30.46 M instr.).
//
// Group order, y pass (bandedGroup): a texel read by this group is read again by the group 8
// rows below. In llvmpipe's order (x fastest) that group runs a whole strip of the image later
// (width x (8 + 2r) texels: 640 KiB at 1024² and r = 16, 1.3 MiB at 2048²), so the texel comes
// back from L3 wherever L2 is smaller. Walking the groups in bands 8 groups (256 texels) wide
// bounds that distance by the band, not the image: r = 16 y went from 3.2-5.1 to 2.3-2.5
// copies in most runs on a Zen 3 EPYC (512 KiB L2), and 3.75 -> 2.2 at 2048². Narrower bands
// lose the prefetched runs along each row (a band of one group cost more at r = 8).

layout(local_size_x = 32, local_size_y = 2) in;

layout(binding = 0, rgba32f) uniform readonly  image2D uSource;
layout(binding = 1, rgba32f) uniform writeonly image2D uDestination;
layout(std430, binding = 0) readonly buffer GaussianWeights { float uWeights[]; };
uniform int   uRadius;     // == SL_BLUR_RADIUS
uniform ivec2 uDirection;  // (1, 0) or (0, 1)
uniform ivec2 uImageSize;

#define R SL_BLUR_RADIUS
// Texels written per invocation. More outputs share more loads, but the window must stay in
// registers: T = 12 or 16 cost more than 8 at r = 8 and 16 (measured, r = 4..16).
#define T 8  // main() writes outputs 0..7: change both together
uniform int uTexelsPerInvocation = T;  // read back by the framework to size the dispatch
#define N (T + 2 * R)                   // window length

vec4 window[N];
float weight[R + 1];

// Loads window[begin .. end): source texels first - R + i along the line, clamped to the edge
// (repeating the border texel is the contract's edge rule).
void loadWindow(int begin, int end, ivec2 first, ivec2 last)
{
    for (int i = begin; i < end; ++i)
        window[i] = imageLoad(uSource, clamp(first + (i - R) * uDirection, ivec2(0), last));
}

void loadWeights(int begin, int end)
{
    for (int k = begin; k < end; ++k)
        weight[k] = uWeights[k];
}

// Output j of this invocation: texel first + j along the line.
void writeOutput(int j, ivec2 first, ivec2 last)
{
    // Symmetric kernel: pair the taps at ±k, r + 1 multiplies instead of 2r + 1.
    vec4 sum = weight[0] * window[j + R];
    for (int k = 1; k <= R / 2; ++k)
        sum += weight[k] * (window[j + R - k] + window[j + R + k]);
    for (int k = R / 2 + 1; k <= R; ++k)
        sum += weight[k] * (window[j + R - k] + window[j + R + k]);
    // A guard rather than an early return: texels past the image are not written.
    ivec2 p = first + j * uDirection;
    if (all(lessThanEqual(p, last)))
        imageStore(uDestination, p, sum);
}

// The work group this one stands for: in the y pass the groups are walked in bands of kBand
// groups, left to right within a band row, band rows top to bottom, band after band; in the x
// pass the order stays llvmpipe's. Float division: llvmpipe has no vector integer division
// (it would divide lane by lane), and the quotients are exact far beyond any group count.
const int kBand = 8;  // groups: 256 texels
ivec2 bandedGroup()
{
    ivec2 groups = ivec2(gl_NumWorkGroups.xy);
    int band = uDirection.y == 1 ? kBand : groups.x;  // x pass: one band, the identity
    int linear = int(gl_WorkGroupID.x) + int(gl_WorkGroupID.y) * groups.x;
    int perBand = min(band, groups.x) * groups.y;
    int b = int((float(linear) + 0.5) / float(perBand));
    int inBand = linear - b * perBand;
    int width = min(band, groups.x - b * band);  // the last band may be narrower
    int row = int((float(inBand) + 0.5) / float(width));
    return ivec2(b * band + inBand - row * width, row);
}

void main()
{
    ivec2 g = bandedGroup() * ivec2(gl_WorkGroupSize.xy) + ivec2(gl_LocalInvocationID.xy);
    ivec2 first = g + g * uDirection * (T - 1);  // stretched by T along the blur direction
    ivec2 last = uImageSize - 1;

    loadWeights(0, R / 2 + 1);
    loadWeights(R / 2 + 1, R + 1);
    // Eight short loops (<= 17 loads each up to r = 64), each unrolled on its own. A loop
    // around them would have to be unrolled first, and Mesa unrolls innermost loops first.
    loadWindow(0, N / 8, first, last);
    loadWindow(N / 8, 2 * N / 8, first, last);
    loadWindow(2 * N / 8, 3 * N / 8, first, last);
    loadWindow(3 * N / 8, 4 * N / 8, first, last);
    loadWindow(4 * N / 8, 5 * N / 8, first, last);
    loadWindow(5 * N / 8, 6 * N / 8, first, last);
    loadWindow(6 * N / 8, 7 * N / 8, first, last);
    loadWindow(7 * N / 8, N, first, last);

    // One call per output (T = 8 of them), for the same reason.

    writeOutput(0, first, last);
    writeOutput(1, first, last);
    writeOutput(2, first, last);
    writeOutput(3, first, last);
    writeOutput(4, first, last);
    writeOutput(5, first, last);
    writeOutput(6, first, last);
    writeOutput(7, first, last);
}
