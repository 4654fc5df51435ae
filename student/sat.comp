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
// yours (two plans below). With plan A, the local_size_x invocations of a group share
// one line and gl_GlobalInvocationID.y is the line index. A line is a row when
// uDirection = (1, 0) and a column when uDirection = (0, 1). The work must be O(n) per
// line. Lines past the image must not be written.
//
// Stub value: until implemented, the pass writes -1 to every texel, which the framework
// reports as "not implemented yet" and previews in magenta. Only a texel of exactly
// (-1, -1, -1, -1) reads as the stub: a table stored with an offset may hold negative values.

// 8 x 32, the reference's shape: llvmpipe runs 8 consecutive invocations along x as one SIMD
// vector, and a group owns local_size_y lines (docs/performance.md, SAT).
layout(local_size_x = 8, local_size_y = 32, local_size_z = 1) in;

layout(binding = 0, rgba32f) uniform readonly  image2D uSource;
layout(binding = 1, rgba32f) uniform writeonly image2D uDestination;
uniform ivec2 uDirection;  // (1, 0): prefix sums along rows; (0, 1): along columns
uniform ivec2 uImageSize;

void main()
{
    bool alongRows  = uDirection.x != 0;
    int  lineLength = alongRows ? uImageSize.x : uImageSize.y;
    int  lineCount  = alongRows ? uImageSize.y : uImageSize.x;
    int  line       = int(gl_GlobalInvocationID.y);
    int  t          = int(gl_LocalInvocationID.x);

    // TODO: not implemented yet: sat.comp (prefix sums along a line)
    // Two plans, both O(n) per line; pick one.
    //  A. Several invocations per line (the classic parallel scan): split the line into
    //     local_size_x contiguous chunks; each invocation sums its chunk; share the chunk
    //     totals through a `shared` array, barrier(), give every chunk its offset (the sum of
    //     the totals before it), and walk the chunk again writing offset + running sum.
    //     barrier() must be reached by every invocation of the work group: do not return
    //     early or branch around it. It reads each texel twice.
    //  B. One invocation per line, walking it once and carrying the running sum: the lean
    //     plan on llvmpipe (2 threads x 8 lanes; a 1024² map has 1024 lines). The 8 lanes of a
    //     vector should be 8 neighbouring lines, so a group's lines go to its first
    //     local_size_y invocations (gl_LocalInvocationIndex) and the rest have nothing to do.
    //     Along rows, 8 lanes reading 8 rows at the same x can land in one L1 cache set:
    //     `./kit bench` shows what that costs on your machine.
    // `./kit bench --exact` gives "sat, rows + columns" on the exact clock: plan B can meet
    // the goal, plan A costs ~1.4x as much there. Make sure any line length works (1, 7, 1000,
    // 4096, ...). Sums grow to ~width·height: think about float32 precision (see the handout);
    // the row pass reads the moments (W × H), the column pass your row pass's 2W × H table.

    // Stub: every texel of this line gets the stub value -1.
    if (line >= lineCount)
        return;
    for (int i = t; i < lineLength; i += int(gl_WorkGroupSize.x)) {
        ivec2 entry = alongRows ? ivec2(i, line) : ivec2(line, i);
        imageStore(uDestination, ivec2(2 * entry.x, entry.y), vec4(-1.0));
        imageStore(uDestination, ivec2(2 * entry.x + 1, entry.y), vec4(-1.0));
    }
}
