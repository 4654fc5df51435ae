// sat.comp: one pass of a summed-area table: inclusive prefix sums along rows or columns.
// The catalogue's SAT base pair (an untiled offset table, an earlier reference): each SAT entry changes one file of the pair and takes the other from here.
//
// Dispatched twice: along rows (uDirection = (1, 0)), then along the columns of the result
// (uDirection = (0, 1)). Afterwards dst holds the summed-area table Σ_{i <= x, j <= y}
// moments(i, j) in an offset form (see "Precision" below), from which sat_lookup.glsl gets
// the mean over a box of any size with a few reads.
//
// Invocation mapping: the framework dispatches 1 × ceil(lineCount / SAT_LINES) work groups.
// A work group owns SAT_LINES consecutive lines (line = gl_WorkGroupID.y · SAT_LINES + ...),
// and each line is shared by SAT_CHUNKS invocations that split it into contiguous chunks:
//   1. each invocation sums its chunk serially;
//   2. after a barrier, each invocation adds up the totals of the chunks before it on its
//      line (its offset);
//   3. it walks its chunk again, writing offset + running sum.
// Work per line: 2n + SAT_CHUNKS image loads, n stores and O(SAT_CHUNKS²) for the offsets, i.e. O(n),
// with a single barrier. Any length n >= 1 works (trailing chunks of a short line are empty).
//
// Which invocation takes which (line, chunk) is ours to choose inside the work group. We put
// consecutive invocations on consecutive *lines*: llvmpipe runs consecutive invocations as
// the lanes of one SIMD batch, so in the column pass the lanes then read 8 neighbouring
// texels of a row (one or two cache lines) instead of 8 texels a chunk apart (about 1.4×
// faster there). Few chunks per line suit a CPU with few cores: with 64 chunks per line and
// one line per work group, both passes were 2-3× slower. Measured on Mesa 22.3 llvmpipe,
// 1024² RGBA32F: about 0.7× the cost of a copy pass along rows, 1.7× along columns.
//
// Precision (docs/numerics.md): a plain float32 table grows to ~(width · height) · moment,
// and its rounding error (~6e-8 relative) swamps a small box's sum once sat_lookup.glsl
// subtracts nearly equal corners: ~1e-2 error on a 1-texel box at the far corner of 1024².
// So we store the table with an offset subtracted. Both passes apply the same rule to
// their line src(0 .. n-1):
//     dst(0) = src(0);                  dst(i) = Σ_{1 <= k <= i} (src(k) - src(0)),  i >= 1.
// After rows then columns, with a = moments(0, 0) and m the moment map:
//     T(0, 0) = a
//     T(x, 0) = Σ_{1<=i<=x} (m(i, 0) - a)                         (first row, x >= 1)
//     T(0, y) = Σ_{1<=j<=y} (m(0, j) - a)                         (first column, y >= 1)
//     T(x, y) = Σ_{1<=i<=x, 1<=j<=y} (m(i,j) - m(0,j) - m(i,0) + a)  (x, y >= 1)
// i.e. sums of *differences* from the first row and column, which stay near 0 wherever the
// depth is smooth (a lit ground plane gives exactly 0). sat_lookup.glsl rebuilds the box
// sum from T exactly in real arithmetic (the offset is a bilinear function of the corner).
// Cost: one extra load per invocation and one subtraction per texel.

#define SAT_CHUNKS 4   // invocations (chunks) per line = local_size_x
#define SAT_LINES  16  // lines per work group        = local_size_y

layout(local_size_x = SAT_CHUNKS, local_size_y = SAT_LINES, local_size_z = 1) in;

layout(binding = 0, rgba32f) uniform readonly  image2D uSource;
layout(binding = 1, rgba32f) uniform writeonly image2D uDestination;
uniform ivec2 uDirection;  // (1, 0): prefix sums along rows; (0, 1): along columns
uniform ivec2 uImageSize;

// Chunk totals of the work group's lines. 16 · 4 · 16 bytes = 1 KiB.
shared vec4 sChunkTotal[SAT_LINES][SAT_CHUNKS];

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

    // Consecutive invocations -> consecutive lines (see above).
    int local = int(gl_LocalInvocationIndex);
    int l     = local % SAT_LINES;  // line within the work group
    int chunk = local / SAT_LINES;  // chunk within the line
    int line  = int(gl_WorkGroupID.y) * SAT_LINES + l;
    // A line past the image (last work group) does no image access, but its invocations
    // still reach the barrier below, as GLSL requires of every invocation.
    bool lineInside = line < lineCount;

    // This invocation's chunk [begin, end) of the line; the last chunks may be short or empty.
    int chunkLength = (lineLength + SAT_CHUNKS - 1) / SAT_CHUNKS;
    int begin = min(chunk * chunkLength, lineLength);
    int end   = min(begin + chunkLength, lineLength);

    // The line's first texel: the offset every other texel of the line is taken relative to.
    vec4 first = lineInside ? imageLoad(uSource, satTexel(0, line, alongRows)) : vec4(0.0);

    // 1. Total of the chunk (of differences; position 0 contributes nothing).
    vec4 total = vec4(0.0);
    if (lineInside) {
        for (int i = max(begin, 1); i < end; ++i)
            total += imageLoad(uSource, satTexel(i, line, alongRows)) - first;
    }
    sChunkTotal[l][chunk] = total;
    barrier();  // the offsets below read the totals of other invocations

    // 2. Offset of this chunk: the sum of everything before it on the line.
    if (!lineInside)
        return;
    vec4 running = vec4(0.0);
    for (int c = 0; c < chunk; ++c)
        running += sChunkTotal[l][c];

    // 3. Walk the chunk again, writing the inclusive prefix sums (position 0 keeps src(0)).
    if (begin == 0 && end > 0)
        imageStore(uDestination, satTexel(0, line, alongRows), first);
    for (int i = max(begin, 1); i < end; ++i) {
        ivec2 texel = satTexel(i, line, alongRows);
        running += imageLoad(uSource, texel) - first;
        imageStore(uDestination, texel, running);
    }
}
