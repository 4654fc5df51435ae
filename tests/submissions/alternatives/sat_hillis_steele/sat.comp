// ALTERNATIVE: recursive doubling (Hillis–Steele) instead of a serial scan over the chunk
// totals. Still correct: it writes the same table as the reference sat.comp (prefix sums of
// differences from the line's first texel, the offset form that the reference
// sat_lookup.glsl next to it undoes: dst(0) = src(0), dst(i) = Σ_{1<=k<=i} (src(k) - src(0)));
// only the order in which float32 adds the terms up differs.
//
// Each line is split into SAT_CHUNKS contiguous chunks, one invocation each:
//   1. each invocation sums its chunk serially;
//   2. the chunk totals of a line are scanned by recursive doubling in shared memory:
//      log2(SAT_CHUNKS) steps, in step s every chunk c >= s adds the partial sum of chunk
//      c - s (Hillis & Steele 1986), ping-ponging between two buffers;
//   3. each invocation walks its chunk again from the scanned total of the chunks before it.
// Work per line: 2n loads, n stores and SAT_CHUNKS · log2(SAT_CHUNKS) additions for step 2,
// i.e. O(n) as the contract requires (a Hillis–Steele scan of the whole line, O(n log n),
// would not be). 64 chunks and 4 lines per work group, unlike the reference's 4 and 16.

#define SAT_CHUNKS 64  // invocations (chunks) per line = local_size_x, a power of two
#define SAT_LINES  4   // lines per work group         = local_size_y

layout(local_size_x = SAT_CHUNKS, local_size_y = SAT_LINES, local_size_z = 1) in;

layout(binding = 0, rgba32f) uniform readonly  image2D uSource;
layout(binding = 1, rgba32f) uniform writeonly image2D uDestination;
uniform ivec2 uDirection;  // (1, 0): prefix sums along rows; (0, 1): along columns
uniform ivec2 uImageSize;

// Two buffers of partial sums for the recursive doubling. 2 · 4 · 64 · 16 bytes = 8 KiB.
shared vec4 sScan[2][SAT_LINES][SAT_CHUNKS];

ivec2 satTexel(int pos, int line, bool alongRows)
{
    return alongRows ? ivec2(pos, line) : ivec2(line, pos);
}

void main()
{
    bool alongRows  = uDirection.x != 0;
    int  lineLength = alongRows ? uImageSize.x : uImageSize.y;
    int  lineCount  = alongRows ? uImageSize.y : uImageSize.x;

    int chunk = int(gl_LocalInvocationID.x);
    int l     = int(gl_LocalInvocationID.y);
    int line  = int(gl_WorkGroupID.y) * SAT_LINES + l;
    bool lineInside = line < lineCount;  // lines past the image: no image access, but barriers

    int chunkLength = (lineLength + SAT_CHUNKS - 1) / SAT_CHUNKS;
    int begin = min(chunk * chunkLength, lineLength);
    int end   = min(begin + chunkLength, lineLength);

    // The line's first texel: every other texel of the line is taken relative to it.
    vec4 first = lineInside ? imageLoad(uSource, satTexel(0, line, alongRows)) : vec4(0.0);

    // 1. Total of the chunk (of differences; position 0 contributes nothing).
    vec4 total = vec4(0.0);
    if (lineInside) {
        for (int i = max(begin, 1); i < end; ++i)
            total += imageLoad(uSource, satTexel(i, line, alongRows)) - first;
    }
    sScan[0][l][chunk] = total;
    barrier();

    // 2. Inclusive scan of the chunk totals by recursive doubling. Every invocation runs the
    //    same number of steps, so the barriers are uniform.
    int from = 0;
    for (int s = 1; s < SAT_CHUNKS; s *= 2) {
        vec4 v = sScan[from][l][chunk];
        if (chunk >= s)
            v += sScan[from][l][chunk - s];
        sScan[1 - from][l][chunk] = v;
        from = 1 - from;
        barrier();
    }

    // 3. Offset: the scanned total of the chunks before this one (0 for the first).
    if (!lineInside)
        return;
    vec4 running = chunk > 0 ? sScan[from][l][chunk - 1] : vec4(0.0);
    if (begin == 0 && end > 0)
        imageStore(uDestination, satTexel(0, line, alongRows), first);  // position 0 keeps src(0)
    for (int i = max(begin, 1); i < end; ++i) {
        ivec2 texel = satTexel(i, line, alongRows);
        running += imageLoad(uSource, texel) - first;
        imageStore(uDestination, texel, running);
    }
}
