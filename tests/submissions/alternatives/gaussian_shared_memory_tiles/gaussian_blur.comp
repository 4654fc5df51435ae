// ALTERNATIVE: shared-memory tiled blur (the classic GPU design) instead of the reference's
// register tile. Still correct: every output texel is the same Σ_{k=-r..r} w_|k|·source(clamp(
// p + k·dir)) with the taps paired as w_k·(a + b), only read from shared memory instead of
// registers, so the result agrees with the reference to float rounding (the loads are the
// same values; the sums are formed in the same order). Image-space mapping with one texel
// per invocation (no uTexelsPerInvocation uniform, so the framework uses T = 1).
//
// (Adapted from an earlier "line space" version, whose mapping put the position along the
// blurred line in gl_GlobalInvocationID.x for both passes; the contract now maps invocations
// to image texels, p = gl_GlobalInvocationID.xy, whatever the direction.)
//
// A work group owns a BLUR_TILE × BLUR_TILE block of output texels. Together its invocations
// first copy the block plus an apron of r texels on both sides along the blur direction into
// shared memory (clamped to the image: the contract's clamp-to-edge), then each invocation
// sums its 2r + 1 taps from shared memory.

#define BLUR_TILE 16  // = local_size_x = local_size_y
#define R SL_BLUR_RADIUS

layout(local_size_x = BLUR_TILE, local_size_y = BLUR_TILE, local_size_z = 1) in;

layout(binding = 0, rgba32f) uniform readonly  image2D uSource;
layout(binding = 1, rgba32f) uniform writeonly image2D uDestination;
layout(std430, binding = 0) readonly buffer GaussianWeights { float uWeights[]; };
uniform int   uRadius;     // == SL_BLUR_RADIUS
uniform ivec2 uDirection;  // (1, 0): blur along rows (x); (0, 1): along columns (y)
uniform ivec2 uImageSize;  // width, height of both images

// sTile[across][along]: `along` runs in the blur direction, tile position along - R.
// 16 · (16 + 2r) · 16 bytes: 6 KiB for r = 4.
shared vec4 sTile[BLUR_TILE][BLUR_TILE + 2 * R];

void main()
{
    ivec2 across = ivec2(uDirection.y, uDirection.x);   // the other axis
    ivec2 origin = ivec2(gl_WorkGroupID.xy) * BLUR_TILE;  // the block's first texel
    ivec2 last   = uImageSize - 1;

    // 1. Cooperative load: BLUR_TILE · (BLUR_TILE + 2R) entries, 256 at a time.
    //    barrier() stays outside every branch: GLSL requires all invocations to reach it.
    const int kEntries = BLUR_TILE * (BLUR_TILE + 2 * R);
    for (int e = int(gl_LocalInvocationIndex); e < kEntries; e += BLUR_TILE * BLUR_TILE) {
        int a = e / (BLUR_TILE + 2 * R);  // across
        int i = e % (BLUR_TILE + 2 * R);  // along, shifted by R
        ivec2 q = origin + a * across + (i - R) * uDirection;
        sTile[a][i] = imageLoad(uSource, clamp(q, ivec2(0), last));
    }
    barrier();  // the taps below read texels loaded by other invocations

    // 2. Convolve. Invocations outside the image write nothing.
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThan(p, last)))
        return;
    ivec2 local = ivec2(gl_LocalInvocationID.xy);
    int a = local.x * across.x + local.y * across.y;               // GLSL has no integer dot()
    int centre = local.x * uDirection.x + local.y * uDirection.y + R;
    vec4 sum = uWeights[0] * sTile[a][centre];
    for (int k = 1; k <= R; ++k)
        sum += uWeights[k] * (sTile[a][centre - k] + sTile[a][centre + k]);
    imageStore(uDestination, p, sum);
}
