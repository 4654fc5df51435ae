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

// 8 x 32, the reference's shape: llvmpipe runs 8 consecutive invocations as one SIMD vector.
// Rows: let those 8 be 8 chunks of one row (8 rows at once share an L1 set at 1024²). Columns:
// let them be 8 neighbouring columns, so each step down reads a run of one row
// (docs/performance.md, SAT).
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
    // A work-efficient plan for the local_size_x invocations of a line:
    //  1. split the line into local_size_x contiguous chunks; each invocation sums its chunk;
    //  2. share the chunk totals through a `shared` array, barrier(), and give every chunk
    //     its offset: the sum of the totals of the chunks before it;
    //  3. each invocation walks its chunk again, writing offset + running sum.
    // barrier() must be reached by every invocation of the work group: do not return early
    // or branch around it. Make sure any line length works (1, 7, 1000, 4096, ...).
    // Sums grow to ~width·height: think about float32 precision (see the handout); the row
    // pass reads the moments (W × H), the column pass your row pass's 2W × H table.

    // Stub: every texel of this line gets the stub value -1.
    if (line >= lineCount)
        return;
    for (int i = t; i < lineLength; i += int(gl_WorkGroupSize.x)) {
        ivec2 entry = alongRows ? ivec2(i, line) : ivec2(line, i);
        imageStore(uDestination, ivec2(2 * entry.x, entry.y), vec4(-1.0));
        imageStore(uDestination, ivec2(2 * entry.x + 1, entry.y), vec4(-1.0));
    }
}
