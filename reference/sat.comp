// sat.comp: one pass of a summed-area table: inclusive prefix sums along rows or columns.
// Reference solution. Stage contract: docs/stage_contract.md.
//
// Dispatched twice: along rows (uDirection = (1, 0)), then along columns of the result
// (uDirection = (0, 1)). Afterwards dst(x, y) = Σ_{i <= x, j <= y} moments(i, j), from which
// sat_lookup.glsl gets the mean over any box with four reads, whatever the box size.
//
// Invocation mapping: the framework dispatches 1 × ceil(lineCount / local_size_y) work
// groups. The SAT_THREADS invocations of a work group share one line
// (gl_GlobalInvocationID.y) and split it into SAT_THREADS contiguous chunks:
//   1. each invocation sums its chunk serially;
//   2. the chunk totals are scanned in shared memory, giving each chunk its offset (the sum
//      of all chunks before it);
//   3. each invocation walks its chunk again, writing offset + running sum.
// Work per line: 2n image loads, n stores and O(SAT_THREADS) for the scan, i.e. O(n), with
// two barriers; any length n >= 1 works (chunks at the end of a short line are empty).
//
// Precision: the sums are accumulated in float32 and grow to ~(width · height) · moment.
// Their rounding error (~6e-8 relative) becomes large next to a small box's sum once
// sat_lookup.glsl subtracts nearly equal corner values. A known fix is to subtract an
// offset (e.g. 0.5, or the map's mean) from every moment before summing, so that the sums
// stay small, and to add it back after the box average. Not done here (a later exercise).

#define SAT_THREADS 64  // invocations per line = local_size_x

layout(local_size_x = SAT_THREADS, local_size_y = 1, local_size_z = 1) in;

layout(binding = 0, rgba32f) uniform readonly  image2D uSource;
layout(binding = 1, rgba32f) uniform writeonly image2D uDestination;
uniform ivec2 uDirection;  // (1, 0): prefix sums along rows; (0, 1): along columns
uniform ivec2 uImageSize;

// Chunk totals, then (after the scan) the inclusive prefix sums of the chunk totals.
// 64 · 16 bytes = 1 KiB.
shared vec4 sChunkSum[SAT_THREADS];

// Image coordinates of position `pos` on line `line`.
ivec2 satTexel(int pos, int line, bool alongRows)
{
    return alongRows ? ivec2(pos, line) : ivec2(line, pos);
}

void main()
{
    bool alongRows  = uDirection.x != 0;
    int  lineLength = alongRows ? uImageSize.x : uImageSize.y;
    int  lineCount  = alongRows ? uImageSize.y : uImageSize.x;
    int  line       = int(gl_GlobalInvocationID.y);
    int  t          = int(gl_LocalInvocationID.x);
    // A line outside the image (last work group) does no image access, but its invocations
    // still take part in the barriers below, which must be reached by all of them.
    bool lineInside = line < lineCount;

    // This invocation's chunk [begin, end) of the line; the last chunks may be short or empty.
    int chunkLength = (lineLength + SAT_THREADS - 1) / SAT_THREADS;
    int begin = min(t * chunkLength, lineLength);
    int end   = min(begin + chunkLength, lineLength);

    // 1. Total of the chunk.
    vec4 total = vec4(0.0);
    if (lineInside) {
        for (int i = begin; i < end; ++i)
            total += imageLoad(uSource, satTexel(i, line, alongRows));
    }
    sChunkSum[t] = total;
    barrier();

    // 2. Inclusive scan of the SAT_THREADS chunk totals. Done serially by one invocation:
    //    64 additions, work-efficient, and only two barriers in the whole shader (a
    //    log-step scan needs 2 barriers per step, which costs more than it saves here, in
    //    particular on a CPU rasterizer that runs the invocations of a group in SIMD batches).
    if (t == 0) {
        vec4 running = vec4(0.0);
        for (int c = 0; c < SAT_THREADS; ++c) {
            running += sChunkSum[c];
            sChunkSum[c] = running;
        }
    }
    barrier();

    // 3. Offset of this chunk = inclusive sum of the chunks before it; walk the chunk again.
    if (!lineInside)
        return;
    vec4 running = (t > 0) ? sChunkSum[t - 1] : vec4(0.0);
    for (int i = begin; i < end; ++i) {
        ivec2 texel = satTexel(i, line, alongRows);
        running += imageLoad(uSource, texel);
        imageStore(uDestination, texel, running);
    }
}
