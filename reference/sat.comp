// sat.comp: one pass of a summed-area table: inclusive prefix sums along rows or columns.
// Reference solution. Stage contract: docs/stage_contract.md.
//
// Dispatched twice: along rows (uDirection = (1, 0)), then along the columns of the result
// (uDirection = (0, 1)). Afterwards dst holds the summed-area table Σ_{i <= x, j <= y}
// moments(i, j) with an offset subtracted (see "Precision" below), from which
// sat_lookup.glsl gets the mean over a box of any size.
//
// Invocation mapping: the framework dispatches 1 × ceil(lineCount / SAT_LINES) work groups.
// A work group owns SAT_LINES consecutive lines (line = gl_WorkGroupID.y · SAT_LINES + ...),
// and its invocations split them into contiguous chunks (rows: SAT_CHUNKS chunks per row;
// columns: SAT_LINES chunks per column, 4 columns per invocation; "Work-group shape" below).
// Chunks are whole tiles (below), so each invocation scans its chunk alone: no shared memory,
// no barrier. Work per line: n image loads and n stores, i.e. O(n). Any length n >= 1 works
// (trailing chunks of a short line are empty).
//
// Precision (docs/numerics.md): a plain float32 table grows to ~(width · height) · moment,
// and its rounding error (~6e-8 relative) swamps a small box's sum once sat_lookup.glsl
// subtracts nearly equal corners: ~3e-2 error on a 1-texel box at the far corner of 1024².
// So we store the table with an offset subtracted, in two ways at once:
//   * tiles: the sums restart every SAT_TILE texels along each line, so the table is made
//     of independent SAT_TILE² tiles and no entry sums more than SAT_TILE² texels;
//   * differences: within a tile segment src(g .. g + SAT_TILE - 1) of a line,
//         dst(g) = src(g);                 dst(i) = Σ_{g < k <= i} (src(k) - src(g)).
// After rows then columns, a tile with origin O holds, with a = m(O) and local coordinates,
//     T(0, 0) = a,   T(x, 0) = Σ_{1<=i<=x} (m(i, 0) - a),   T(0, y) = Σ_{1<=j<=y} (m(0, j) - a),
//     T(x, y) = Σ_{1<=i<=x, 1<=j<=y} (m(i,j) - m(0,j) - m(i,0) + a)      (x, y >= 1):
// sums of differences that stay 0 on smooth depth (a lit ground plane) and small elsewhere.
// sat_lookup.glsl rebuilds the box sum from them, tile by tile.
// Measured on Mesa 22.3 llvmpipe, 1024² RGBA32F: docs/numerics.md, "Speed".

// Work-group shape, measured on llvmpipe (docs/performance.md, SAT): llvmpipe runs 8
// consecutive invocations as the lanes of one SIMD vector, so invocation i takes the role
// i % 8 among 8 and its chunk from i / 8 in both passes:
//   rows:    the 8 lanes are 8 chunks of one row (8 rows at once would be 16 KiB apart at
//            1024², all in one L1 set (address mod 4 KiB) with the rows they write, more
//            lines than its 8 ways: 1.6 copies instead of 1.0-1.2 on a Zen 3 EPYC);
//   columns: the 8 lanes are 8 quads of neighbouring columns, 4 columns per invocation, so
//            each step down reads a 512-byte run of a row (one cache line per lane) and has
//            8 independent lines in flight: 2.8 copies with one column per invocation, 1.4
//            with four, at 1024² on a Zen 3 EPYC, where a walk down columns waits on memory.
// The table does not depend on the shape: the sums restart at every tile.
#define SAT_CHUNKS 8   // local_size_x: chunks per row (row pass), column quads (column pass)
#define SAT_LINES  32  // local_size_y: lines per work group (the framework's dispatch unit)
#define SAT_TILE   32  // tile size; must equal SAT_TILE in sat_lookup.glsl
#define SAT_QUAD   4   // columns per invocation in the column pass

layout(local_size_x = SAT_CHUNKS, local_size_y = SAT_LINES, local_size_z = 1) in;

layout(binding = 0, rgba32f) uniform readonly  image2D uSource;
layout(binding = 1, rgba32f) uniform writeonly image2D uDestination;
uniform ivec2 uDirection;  // (1, 0): prefix sums along rows; (0, 1): along columns
uniform ivec2 uImageSize;

// Chunk `chunk` of `chunks` along a line of length n: [begin, end), a whole number of tiles
// (the last may be short, trailing ones empty).
ivec2 chunkRange(int chunk, int chunks, int n)
{
    int tilesPerChunk = ((n + SAT_TILE - 1) / SAT_TILE + chunks - 1) / chunks;
    int begin = min(chunk * tilesPerChunk * SAT_TILE, n);
    return ivec2(begin, min(begin + tilesPerChunk * SAT_TILE, n));
}

// One step of a tile segment's scan at position i of the line: at a tile's first texel
// first = v and dst = v; after it running += v - first and dst = running. Selects, not an
// if/else: llvmpipe runs both sides of a branch, and each side held a store.
vec4 scanStep(int i, vec4 v, inout vec4 first, inout vec4 running)
{
    bool start = i % SAT_TILE == 0;
    first = start ? v : first;
    running = start ? vec4(0.0) : running + (v - first);
    return start ? first : running;
}

// Row pass: texels [begin, end) of row `row`.
void scanRow(int row, ivec2 range)
{
    vec4 first = vec4(0.0), running = vec4(0.0);
    for (int i = range.x; i < range.y; ++i) {
        ivec2 texel = ivec2(i, row);
        imageStore(uDestination, texel, scanStep(i, imageLoad(uSource, texel), first, running));
    }
}

// Column pass: texels [begin, end) of the SAT_QUAD columns from `column` on (those left of
// `columns`), walked down together.
void scanColumns(int column, int columns, ivec2 range)
{
    vec4 first[SAT_QUAD], running[SAT_QUAD];
    for (int c = 0; c < SAT_QUAD; ++c)
        first[c] = running[c] = vec4(0.0);
    for (int i = range.x; i < range.y; ++i) {
        vec4 v[SAT_QUAD];
        for (int c = 0; c < SAT_QUAD; ++c)  // all loads first: they are independent
            v[c] = imageLoad(uSource, ivec2(column + c, i));
        for (int c = 0; c < SAT_QUAD; ++c) {
            vec4 sum = scanStep(i, v[c], first[c], running[c]);
            if (column + c < columns)
                imageStore(uDestination, ivec2(column + c, i), sum);
        }
    }
}

void main()
{
    int local = int(gl_LocalInvocationIndex);
    int lane = local % SAT_CHUNKS, slot = local / SAT_CHUNKS;
    int firstLine = int(gl_WorkGroupID.y) * SAT_LINES;
    if (uDirection.x != 0) {
        // Row firstLine + slot, chunk `lane` of SAT_CHUNKS.
        int row = firstLine + slot;
        if (row < uImageSize.y)
            scanRow(row, chunkRange(lane, SAT_CHUNKS, uImageSize.x));
    } else {
        // Columns firstLine + SAT_QUAD·lane ..., chunk `slot` of SAT_LINES (the group's
        // SAT_LINES columns are SAT_CHUNKS quads).
        int column = firstLine + SAT_QUAD * lane;
        if (column < uImageSize.x)
            scanColumns(column, uImageSize.x, chunkRange(slot, SAT_LINES, uImageSize.y));
    }
}
