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
// SAT_CHUNKS × SAT_LINES invocations; a group owns SAT_LINES consecutive lines. Each line is
// cut into contiguous chunks, one per invocation: the invocation sums its chunk, the chunk
// totals go through shared memory, and after one barrier each invocation walks its chunk
// again from the sum of the chunks before it. Work per line: 2n loads and n entry stores,
// O(n). Any length n >= 1 works (trailing chunks of a short line are empty).
//
// Work-group shape (docs/performance.md, SAT): llvmpipe runs 8 consecutive invocations as
// the lanes of one SIMD vector. Rows: the 8 lanes are 8 chunks of one row (8 rows at once
// would be 16 KiB apart at 1024², all in one L1 set). Columns: the 8 lanes are 8
// neighbouring columns, so each step down reads one run of a row.
#define SAT_CHUNKS 8   // local_size_x
#define SAT_LINES  32  // local_size_y: lines per work group (the framework's dispatch unit)

layout(local_size_x = SAT_CHUNKS, local_size_y = SAT_LINES, local_size_z = 1) in;

layout(binding = 0, rgba32f) uniform readonly  image2D uSource;
layout(binding = 1, rgba32f) uniform writeonly image2D uDestination;
uniform ivec2 uDirection;  // (1, 0): prefix sums along rows; (0, 1): along columns
uniform ivec2 uImageSize;  // the moment map's width and height (the table is twice as wide)

// One chunk total per invocation.
shared dvec4 sTotals[SAT_CHUNKS * SAT_LINES];

// Chunk `chunk` of `chunks` along a line of length n: [begin, end) (trailing ones empty).
ivec2 chunkRange(int chunk, int chunks, int n)
{
    int length = (n + chunks - 1) / chunks;
    int begin = min(chunk * length, n);
    return ivec2(begin, min(begin + length, n));
}

// Entry x of line `line`: the row pass reads the moment map, the column pass the row pass's
// two-texel entries.
dvec4 loadEntry(bool alongRows, int line, int x)
{
    if (alongRows)
        return dvec4(imageLoad(uSource, ivec2(x, line)));
    ivec2 t = ivec2(2 * line, x);
    return dvec4(imageLoad(uSource, t)) + dvec4(imageLoad(uSource, t + ivec2(1, 0)));
}

// Stores a sum as its nearest float and the float nearest the rest.
void storeEntry(ivec2 entry, dvec4 sum)
{
    precise vec4 high = vec4(sum);  // precise: else a compiler may fold sum - double(float(sum)) to 0
    imageStore(uDestination, ivec2(2 * entry.x, entry.y), high);
    imageStore(uDestination, ivec2(2 * entry.x + 1, entry.y), vec4(sum - dvec4(high)));
}

void main()
{
    int local = int(gl_LocalInvocationIndex);
    int lane = local % SAT_CHUNKS, slot = local / SAT_CHUNKS;
    int firstLine = int(gl_WorkGroupID.y) * SAT_LINES;
    bool alongRows = uDirection.x != 0;
    int lineLength = alongRows ? uImageSize.x : uImageSize.y;
    int lineCount  = alongRows ? uImageSize.y : uImageSize.x;
    // Rows: row firstLine + slot, chunk `lane` of SAT_CHUNKS. Columns: the 8 lanes are 8
    // neighbouring columns, the group's 32 columns 4 such runs; each column has 8 chunks.
    int line  = alongRows ? firstLine + slot : firstLine + lane + SAT_CHUNKS * (slot % 4);
    int chunk = alongRows ? lane : slot / 4;
    bool live = line < lineCount;
    ivec2 range = live ? chunkRange(chunk, SAT_CHUNKS, lineLength) : ivec2(0);

    dvec4 total = dvec4(0.0);
    for (int i = range.x; i < range.y; ++i)
        total += loadEntry(alongRows, line, i);
    sTotals[local] = total;
    barrier();  // reached by every invocation: no early return above

    // The sum of the chunks before this one, of the same line.
    dvec4 running = dvec4(0.0);
    for (int k = 0; k < chunk; ++k)
        running += sTotals[alongRows ? slot * SAT_CHUNKS + k : (4 * k + slot % 4) * SAT_CHUNKS + lane];
    for (int i = range.x; i < range.y; ++i) {
        running += loadEntry(alongRows, line, i);
        storeEntry(alongRows ? ivec2(i, line) : ivec2(line, i), running);
    }
}
