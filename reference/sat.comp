// sat.comp: one pass of a summed-area table: inclusive prefix sums along rows or columns.
// Reference solution. Stage contract: docs/stage_contract.md.
//
// Dispatched twice: along rows (uDirection = (1, 0)), then along the columns of the result
// (uDirection = (0, 1)). Afterwards the table holds S(x, y) = Σ_{i <= x, j <= y} m(i, j), the
// summed-area table, from which sat_lookup.glsl gets the mean over a box of any size in four
// corner reads.
//
// Precision (docs/numerics.md): S grows to ~(width · height) · moment, and a float32 entry of
// that size is off by ~6e-8 of it: ~3e-2 on a 1-texel box at the far corner of 1024² once
// the lookup subtracts nearly equal corners. So the sums are kept in double and each entry is
// stored in the two texels the framework gives it (the table is 2W × H): the float nearest
// the sum at (2x, y) and the float nearest what is left at (2x + 1, y). Their sum holds ~48
// bits, so a box's corners cancel to ~1e-7 of an entry's size whatever the box.
//
// Invocation mapping: the framework dispatches 1 × ceil(lineCount / SAT_LINES) work groups of
// SAT_LANES × SAT_LINES invocations; a group owns SAT_LINES consecutive lines. One invocation
// walks one whole line once, carrying the running sum S along it: n loads and n entry stores
// per line, O(n), no shared memory and no barrier. A line of 1024 texels is a long walk, but
// llvmpipe has only 2 threads × 8 lanes: a 1024² map's 1024 lines keep every lane busy. (A
// GPU with thousands of lanes would want several invocations per line: sum chunks, share
// their totals, walk again; that reads each texel twice and costs ~1.4× here.)
//
// Lanes (docs/performance.md, SAT): llvmpipe runs 8 consecutive invocations along x as the
// lanes of one SIMD vector, so the group's first SAT_LINES invocations (SAT_LINES / 8 vectors)
// take its lines, 8 neighbouring lines to a vector, and the other vectors end at once (the
// contract gives a group local_size_y lines, and a vector needs 8 of them). Columns: each step
// down reads one 256-byte run of a row. Rows: lane k walks SAT_ROW_LAG · k texels behind lane
// 0, so the 8 rows a vector reads at one step (16 KiB apart at 1024²) are not all in one L1 set.
#define SAT_LANES   8   // local_size_x: one SIMD vector
#define SAT_LINES   32  // local_size_y: lines per work group (the framework's dispatch unit)
#define SAT_ROW_LAG 4   // texels (one 64-byte cache line of the moment map)

layout(local_size_x = SAT_LANES, local_size_y = SAT_LINES, local_size_z = 1) in;

layout(binding = 0, rgba32f) uniform readonly  image2D uSource;
layout(binding = 1, rgba32f) uniform writeonly image2D uDestination;
uniform ivec2 uDirection;  // (1, 0): prefix sums along rows; (0, 1): along columns
uniform ivec2 uImageSize;  // the moment map's width and height (the table is twice as wide)

// Entry i of line `line`: the row pass reads the moment map, the column pass the row pass's
// two-texel entries.
dvec4 loadEntry(bool alongRows, int line, int i)
{
    if (alongRows)
        return dvec4(imageLoad(uSource, ivec2(i, line)));
    ivec2 t = ivec2(2 * line, i);
    return dvec4(imageLoad(uSource, t)) + dvec4(imageLoad(uSource, t + ivec2(1, 0)));
}

// Stores a sum as its nearest float and the float nearest the rest.
void storeEntry(ivec2 entry, dvec4 sum)
{
    precise vec4 high = vec4(sum);  // precise: else a compiler may fold sum - double(float(sum)) to 0
    imageStore(uDestination, ivec2(2 * entry.x, entry.y), high);
    imageStore(uDestination, ivec2(2 * entry.x + 1, entry.y), vec4(sum - dvec4(high)));
}

// Walks line `line` (n entries) once, storing S(i) = S(i - 1) + src(i) at each i, `lag` steps
// behind a walk of `steps` steps. Called with a constant `alongRows`, so each pass compiles
// to its own loop (a loop that tests the direction at every step costs ~12 % more).
void walkLine(bool alongRows, int line, int n, int lag, int steps)
{
    dvec4 S = dvec4(0.0);
    for (int step = 0; step < steps; ++step) {
        int i = step - lag;
        if (i < 0 || i >= n)
            continue;
        S += loadEntry(alongRows, line, i);
        storeEntry(alongRows ? ivec2(i, line) : ivec2(line, i), S);
    }
}

void main()
{
    int local = int(gl_LocalInvocationIndex);
    int line = int(gl_WorkGroupID.y) * SAT_LINES + local;
    if (uDirection.x != 0) {
        if (local < SAT_LINES && line < uImageSize.y)
            walkLine(true, line, uImageSize.x, SAT_ROW_LAG * (local % SAT_LANES),
                     uImageSize.x + SAT_ROW_LAG * (SAT_LANES - 1));
    } else {
        if (local < SAT_LINES && line < uImageSize.x)
            walkLine(false, line, uImageSize.y, 0, uImageSize.y);
    }
}
