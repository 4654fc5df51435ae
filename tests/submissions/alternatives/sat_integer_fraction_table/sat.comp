// ALTERNATIVE: written from the student kit alone: one invocation walks each line in double; an entry holds floor(S) and S - floor(S)
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

// Design (this solution): one invocation per line, walking it sequentially from 0 to n-1 and
// keeping the running sum in double (O(n) per line, no shared memory, no barrier). The 8
// consecutive invocations llvmpipe runs as one SIMD vector are 8 neighbouring lines: in the
// column pass they read 8 neighbouring entries of one row at each step.
//
// Encoding of an entry's two texels: the double sum S is split at the fixed power of two
// 2^0: texel 2x holds floor(S) (an integer; exact in float32 since S <= W·H <= 2^24), texel
// 2x + 1 holds the fraction S − floor(S) in [0, 1), rounded to float32 (error <= 2^-25).
// Both are non-negative, so no entry can read as the stub (−1, −1, −1, −1).
layout(local_size_x = 1, local_size_y = 64, local_size_z = 1) in;

layout(binding = 0, rgba32f) uniform readonly  image2D uSource;
layout(binding = 1, rgba32f) uniform writeonly image2D uDestination;
uniform ivec2 uDirection;  // (1, 0): prefix sums along rows; (0, 1): along columns
uniform ivec2 uImageSize;

void storeEntry(ivec2 entry, dvec4 sum)
{
    precise dvec4 whole = floor(sum);
    precise dvec4 frac = sum - whole;
    imageStore(uDestination, ivec2(2 * entry.x, entry.y), vec4(whole));
    imageStore(uDestination, ivec2(2 * entry.x + 1, entry.y), vec4(frac));
}

void main()
{
    bool alongRows  = uDirection.x != 0;
    int  lineLength = alongRows ? uImageSize.x : uImageSize.y;
    int  lineCount  = alongRows ? uImageSize.y : uImageSize.x;
    int  line       = int(gl_GlobalInvocationID.y);
    if (line >= lineCount)
        return;

    dvec4 sum = dvec4(0.0);
    if (alongRows) {
        // Row pass: the source is the W x H moment map.
        for (int i = 0; i < lineLength; ++i) {
            ivec2 entry = ivec2(i, line);
            sum += dvec4(imageLoad(uSource, entry));
            storeEntry(entry, sum);
        }
    } else {
        // Column pass: the source is the row pass's 2W x H table (whole, fraction).
        for (int i = 0; i < lineLength; ++i) {
            ivec2 entry = ivec2(line, i);
            dvec4 whole = dvec4(imageLoad(uSource, ivec2(2 * entry.x, entry.y)));
            dvec4 frac  = dvec4(imageLoad(uSource, ivec2(2 * entry.x + 1, entry.y)));
            sum += whole + frac;
            storeEntry(entry, sum);
        }
    }
}
