// gaussian_blur.comp: one pass of a separable Gaussian blur of the moment map.
// Reference solution. Stage contract: docs/stage_contract.md.
//
// Dispatched twice, along x then y (uDirection). Moments are linear in the depth
// distribution, so blurring them gives the moments of the blurred distribution: this is
// what makes moment shadow maps filterable (unlike depth maps, which need PCF).
//
// Invocation mapping ("line space"): gl_GlobalInvocationID.x is the position along the line
// being blurred and gl_GlobalInvocationID.y the index of the line (a row when blurring along
// x, a column along y). The framework dispatches
//     ceil(lineLength / BLUR_TILE) × ceil(lineCount / 1) work groups.
//
// Tiling: the work group's BLUR_TILE invocations blur BLUR_TILE consecutive texels of one
// line. Together they first copy their tile plus an apron of r texels on each side into
// shared memory (about one image load per texel instead of 2r + 1), then every invocation
// sums its 2r + 1 taps from shared memory.

#define BLUR_TILE       128  // texels per work group = local_size_x
#define BLUR_MAX_RADIUS 64   // largest uRadius supported; shared memory is sized for it

layout(local_size_x = BLUR_TILE, local_size_y = 1, local_size_z = 1) in;

layout(binding = 0, rgba32f) uniform readonly  image2D uSource;
layout(binding = 1, rgba32f) uniform writeonly image2D uDestination;
layout(std430, binding = 0) readonly buffer GaussianWeights { float uWeights[]; };
uniform int   uRadius;     // r: the kernel has 2r + 1 taps, weights uWeights[0..r]
uniform ivec2 uDirection;  // (1, 0): blur along rows (x); (0, 1): along columns (y)
uniform ivec2 uImageSize;  // width, height of both images

// The tile and its aprons: sTile[i] holds line position tileStart + i (clamped to the line).
// (128 + 2·64) · 16 bytes = 4 KiB.
shared vec4 sTile[BLUR_TILE + 2 * BLUR_MAX_RADIUS];

// Image coordinates of position `pos` on line `line`.
ivec2 blurTexel(int pos, int line, bool alongRows)
{
    return alongRows ? ivec2(pos, line) : ivec2(line, pos);
}

void main()
{
    int  r          = clamp(uRadius, 0, BLUR_MAX_RADIUS);
    bool alongRows  = uDirection.x != 0;
    int  lineLength = alongRows ? uImageSize.x : uImageSize.y;
    int  lineCount  = alongRows ? uImageSize.y : uImageSize.x;
    int  line       = int(gl_GlobalInvocationID.y);
    int  local      = int(gl_LocalInvocationID.x);
    int  tileStart  = int(gl_WorkGroupID.x) * BLUR_TILE - r;  // line position of sTile[0]

    // 1. Load the tile and its aprons, each entry once. Positions outside the line are
    //    clamped to its ends, which repeats the edge texel (the contract's clamp-to-edge).
    //    Entries past lineLength - 1 + r feed no output: the last tile of a line skips them.
    //    barrier() stays outside every branch: GLSL requires all invocations to reach it.
    int count = min(BLUR_TILE + 2 * r, lineLength + r - tileStart);
    if (line < lineCount) {
        for (int i = local; i < count; i += BLUR_TILE) {
            int pos = clamp(tileStart + i, 0, lineLength - 1);
            sTile[i] = imageLoad(uSource, blurTexel(pos, line, alongRows));
        }
    }
    barrier();  // the taps below read texels loaded by other invocations

    // 2. Convolve. Invocations past the end of the line (or of the image) write nothing.
    int pos = int(gl_GlobalInvocationID.x);
    if (line >= lineCount || pos >= lineLength)
        return;
    // The kernel is symmetric: pair the taps at ±k and multiply once, w_k·(a + b),
    // which halves the multiplies of Σ w_|k|·source(p + k).
    int centre = local + r;
    vec4 sum = uWeights[0] * sTile[centre];
    for (int k = 1; k <= r; ++k)
        sum += uWeights[k] * (sTile[centre - k] + sTile[centre + k]);
    imageStore(uDestination, blurTexel(pos, line, alongRows), sum);
}
