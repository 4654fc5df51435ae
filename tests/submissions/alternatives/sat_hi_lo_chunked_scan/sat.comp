// ALTERNATIVE: written from the student kit alone: each entry a double prefix sum as hi = float(S), lo = float(S - hi); 8 chunks a line, chunk totals in shared dvec4
// sat.comp: one pass of a summed-area table: inclusive prefix sums along rows or columns.
// Stage contract: docs/stage_contract.md (the part that concerns this file is repeated here).
//
// Filter pass, compute shader. Do not write a #version line: the framework prepends
// `#version 450 core`. Dispatched twice: along rows (uDirection = (1, 0)), then along the
// columns of the result (uDirection = (0, 1)).
//
// Inputs and outputs:
//   uSource       (image binding 0, RGBA32F, read only)   rows: the W × H moment map;
//                                                          columns: your row pass's table
//   uDestination  (image binding 1, RGBA32F, write only)  the table: 2W × H texels, two per
//                                                          entry of the W × H map
//   uDirection    (1, 0): prefix sums along rows; (0, 1): along columns
//   uImageSize    W, H: the moment map's width and height (each side 1 .. 4096)
// Writes the inclusive prefix sum along each line: S(i) = Σ_{k <= i} src(k). After both
// passes S(x, y) = Σ_{i <= x, j <= y} moments(i, j), a summed-area table.
// Each entry (x, y) has two texels, (2x, y) and (2x + 1, y): what they hold is yours, as long
// as your sat_lookup.glsl reads it back (the pair is graded together on the box averages it
// returns). Why two: S grows to ~W·H, and one float32 of that size is too coarse for a small
// box (see the handout); for example keep the sums in double and store the float nearest the
// sum plus the float nearest the rest.
//
// Invocation mapping: the framework dispatches 1 × ceil(lineCount / local_size_y) work
// groups, reading the local size you declare. Work group k owns lines k·local_size_y …
// (local_size_y of them) along their whole length; how its invocations share them is
// yours. The simplest plan: the local_size_x invocations of a group share one line and
// gl_GlobalInvocationID.y is the line index. A line is a row when uDirection = (1, 0) and a
// column when uDirection = (0, 1). The work must be O(n) per line. Lines past the image must
// not be written.
//
// Stub value: until implemented, the pass writes -1 to every texel, which the framework
// reports as "not implemented yet" and previews in magenta. Only a texel of exactly
// (-1, -1, -1, -1) reads as the stub: a table stored with an offset may hold negative values.

// 8 x 32: 32 lines per work group, 8 invocations (chunks) per line. llvmpipe runs 8
// consecutive invocations (gl_LocalInvocationIndex) as one SIMD vector, so the lane mapping
// differs per pass (docs/performance.md, SAT):
//   rows:    the 8 lanes of a vector are the 8 chunks of one row;
//   columns: the 8 lanes are 8 neighbouring columns, in the same chunk, so each step down reads
//            one run of a row.
#define SAT_CHUNKS 8
#define SAT_LINES  32
layout(local_size_x = SAT_CHUNKS, local_size_y = SAT_LINES, local_size_z = 1) in;

layout(binding = 0, rgba32f) uniform readonly  image2D uSource;
layout(binding = 1, rgba32f) uniform writeonly image2D uDestination;
uniform ivec2 uDirection;  // (1, 0): prefix sums along rows; (0, 1): along columns
uniform ivec2 uImageSize;

// Table encoding: entry (x, y) holds the double prefix sum S as two floats,
//   texel (2x, y)     = hi = the float nearest S
//   texel (2x + 1, y) = lo = the float nearest S - hi
// so that double(hi) + double(lo) keeps ~48 bits of S (exact for a sum of < 2^24 floats of
// one binade, far more than a 4096² map needs).
void storeEntry(ivec2 entry, dvec4 sum)
{
    precise vec4 hi = vec4(sum);
    precise dvec4 rest = sum - dvec4(hi);
    vec4 lo = vec4(rest);
    imageStore(uDestination, ivec2(2 * entry.x, entry.y), hi);
    imageStore(uDestination, ivec2(2 * entry.x + 1, entry.y), lo);
}

// Chunk totals of every line of the group, shared for the offsets.
shared dvec4 sChunkTotal[SAT_CHUNKS][SAT_LINES];

void main()
{
    bool alongRows  = uDirection.x != 0;
    int  lineLength = alongRows ? uImageSize.x : uImageSize.y;
    int  lineCount  = alongRows ? uImageSize.y : uImageSize.x;

    int index = int(gl_LocalInvocationIndex);           // x + SAT_CHUNKS·y
    int lineInGroup, chunk;
    if (alongRows) {
        chunk       = int(gl_LocalInvocationID.x);
        lineInGroup = int(gl_LocalInvocationID.y);
    } else {
        lineInGroup = index % SAT_LINES;
        chunk       = index / SAT_LINES;
    }
    int  line  = int(gl_WorkGroupID.y) * SAT_LINES + lineInGroup;
    bool valid = line < lineCount;

    int chunkLength = (lineLength + SAT_CHUNKS - 1) / SAT_CHUNKS;
    int begin = min(chunk * chunkLength, lineLength);
    int end   = min(begin + chunkLength, lineLength);
    if (!valid)
        end = begin;                                      // no work, but still reach barrier()

    // 1. This chunk's total, in double (one loop per pass: no branch inside the loops).
    dvec4 total = dvec4(0.0);
    if (alongRows) {
        for (int i = begin; i < end; ++i)
            total += dvec4(imageLoad(uSource, ivec2(i, line)));
    } else {
        for (int i = begin; i < end; ++i)
            total += dvec4(imageLoad(uSource, ivec2(2 * line, i)))
                   + dvec4(imageLoad(uSource, ivec2(2 * line + 1, i)));
    }
    sChunkTotal[chunk][lineInGroup] = total;
    barrier();

    // 2. The offset of this chunk: the totals of the chunks before it.
    dvec4 sum = dvec4(0.0);
    for (int c = 0; c < SAT_CHUNKS; ++c) {
        if (c < chunk)
            sum += sChunkTotal[c][lineInGroup];
    }

    // 3. Walk the chunk again: inclusive prefix sums.
    if (alongRows) {
        for (int i = begin; i < end; ++i) {
            sum += dvec4(imageLoad(uSource, ivec2(i, line)));
            storeEntry(ivec2(i, line), sum);
        }
    } else {
        for (int i = begin; i < end; ++i) {
            sum += dvec4(imageLoad(uSource, ivec2(2 * line, i)))
                 + dvec4(imageLoad(uSource, ivec2(2 * line + 1, i)));
            storeEntry(ivec2(line, i), sum);
        }
    }
}
