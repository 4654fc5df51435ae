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
// and each line is shared by SAT_CHUNKS invocations that split it into contiguous chunks.
// Chunks are whole tiles (below), so each invocation scans its chunk alone: no shared memory,
// no barrier. Work per line: n image loads and n stores, i.e. O(n). Any length n >= 1 works
// (trailing chunks of a short line are empty). llvmpipe runs 8 consecutive invocations as the
// lanes of one SIMD batch, so the mapping differs per pass. Columns: consecutive invocations
// take consecutive *lines*, and the lanes read neighbouring texels of a row (about 1.4× faster
// there). Rows: consecutive invocations take consecutive *chunks* of one line; 8 lines at once
// would be 8 rows 16 KiB apart at 1024², all in the same L1 set (set index = address mod
// 4 KiB) with the 8 rows they write, more lines than its 8 ways: row pass 1.6 -> 1.2 copies on a
// Zen 3 EPYC (at 1000², where rows do not alias, both mappings cost 1.05-1.2).
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

// Measured (docs/performance.md): 16 chunks per line (short scans: 2 tiles each on 1024²) and
// 16 lines per group, at least one SIMD vector of lines (8 lanes at 256 bits; 4 lines cost
// 2.1 copies, lanes then straddle two chunks). 4 chunks cost 1.6-2.0 copies, 16 chunks 1.2-1.5.
// The table does not depend on them: the sums restart at every tile.
#define SAT_CHUNKS 16  // invocations (chunks) per line = local_size_x
#define SAT_LINES  16  // lines per work group        = local_size_y
#define SAT_TILE   32  // tile size; must equal SAT_TILE in sat_lookup.glsl

layout(local_size_x = SAT_CHUNKS, local_size_y = SAT_LINES, local_size_z = 1) in;

layout(binding = 0, rgba32f) uniform readonly  image2D uSource;
layout(binding = 1, rgba32f) uniform writeonly image2D uDestination;
uniform ivec2 uDirection;  // (1, 0): prefix sums along rows; (0, 1): along columns
uniform ivec2 uImageSize;

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

    // Consecutive invocations -> consecutive chunks of a row, or consecutive columns (above).
    int local = int(gl_LocalInvocationIndex);
    int l     = alongRows ? local / SAT_CHUNKS : local % SAT_LINES;  // line within the work group
    int chunk = alongRows ? local % SAT_CHUNKS : local / SAT_LINES;  // chunk within the line
    int line  = int(gl_WorkGroupID.y) * SAT_LINES + l;
    if (line >= lineCount)
        return;

    // This invocation's chunk [begin, end): a whole number of tiles (the last may be short).
    int tilesPerChunk = ((lineLength + SAT_TILE - 1) / SAT_TILE + SAT_CHUNKS - 1) / SAT_CHUNKS;
    int begin = min(chunk * tilesPerChunk * SAT_TILE, lineLength);
    int end   = min(begin + tilesPerChunk * SAT_TILE, lineLength);

    vec4 first = vec4(0.0);    // src at the start of the current tile segment
    vec4 running = vec4(0.0);  // Σ (src(k) - first) over the segment so far
    for (int i = begin; i < end; ++i) {
        ivec2 texel = satTexel(i, line, alongRows);
        vec4 v = imageLoad(uSource, texel);
        if (i % SAT_TILE == 0) {
            first = v;
            running = vec4(0.0);
            imageStore(uDestination, texel, first);
        } else {
            running += v - first;
            imageStore(uDestination, texel, running);
        }
    }
}
