// ALTERNATIVE: written from the student kit alone: integer parts differenced first, then the fractions (float32); its own satKernelTexels
// sat_lookup.glsl: box average of the moment map from its summed-area table, and the box
// each pixel chooses from its situation.
// Stage contract: docs/stage_contract.md (the part that concerns this file is repeated here).
//
// Included by the lighting pass and by shaders/sat_resolve.comp when the filter is a
// summed-area table (SAT). Do not write a #version line: the framework prepends
// `#version 450 core`.
//
// // The table (see sat.comp): entry (i, j) = W + F, texel (2i, j) holding W = floor(S(i, j)) (an
// integer, exact in float32) and texel (2i + 1, j) the fraction F = S − W in [0, 1).
// The lookup works in float32 without losing the small box: it never forms a large S. The
// bilinear corners are rewritten as 3 x 3 differences of entries (the box, its edge strips and
// edge texels), and each difference is taken on the integer parts first: a difference of
// integers below 2^24 is exact in float32, so what is rounded is only as large as the part
// of the box it belongs to.
struct SatEntry { vec4 w; vec4 f; };

SatEntry satEntry(sampler2D sat, ivec2 idx)
{
    // S(-1, .) = S(., -1) = 0: never fetch outside the table.
    SatEntry e;
    if (idx.x < 0 || idx.y < 0) {
        e.w = vec4(0.0);
        e.f = vec4(0.0);
    } else {
        e.w = texelFetch(sat, ivec2(2 * idx.x, idx.y), 0);
        e.f = texelFetch(sat, ivec2(2 * idx.x + 1, idx.y), 0);
    }
    return e;
}

// Difference of two differences of entries, a - b - (c - d), integer parts first.
vec4 satDD(SatEntry a, SatEntry b, SatEntry c, SatEntry d)
{
    vec4 w = (a.w - b.w) - (c.w - d.w);        // exact: integers below 2^24
    vec4 f = (a.f - b.f) - (c.f - d.f);
    return w + f;
}

vec4 satBoxAverage(sampler2D sat, vec2 center, vec2 boxSize)
{
    ivec2 tableSize = textureSize(sat, 0);
    ivec2 size = ivec2(tableSize.x / 2, tableSize.y);
    vec2 lo = clamp(center - 0.5 * boxSize, vec2(0.0), vec2(size));
    vec2 hi = clamp(center + 0.5 * boxSize, vec2(0.0), vec2(size));
    vec2 extent = hi - lo;
    float area = extent.x * extent.y;
    if (!(area > 0.0))
        return vec4(0.0);                       // a box entirely outside the map

    // The sum left of an edge e is S interpolated at u = e - 1: S(i) + f·(S(i + 1) − S(i)),
    // i = floor(u) in [-1, size - 1], f = u - i (0 where i + 1 would be past the end).
    vec2 u0 = lo - 1.0, u1 = hi - 1.0;
    vec2 fl0 = floor(u0), fl1 = floor(u1);
    vec2 f0 = u0 - fl0, f1 = u1 - fl1;
    ivec2 a = ivec2(fl0), c = ivec2(fl1);      // the low and the high edge's entries
    ivec2 b = min(a + 1, size - 1), d = min(c + 1, size - 1);

    // Along x the box sum is  [S(c) − S(a)] + f1.x·[S(d) − S(c)] − f0.x·[S(b) − S(a)],
    // the same along y: 3 x 3 terms, each a double difference of four entries.
    SatEntry aa = satEntry(sat, ivec2(a.x, a.y)), ba = satEntry(sat, ivec2(b.x, a.y));
    SatEntry ca = satEntry(sat, ivec2(c.x, a.y)), da = satEntry(sat, ivec2(d.x, a.y));
    SatEntry ab = satEntry(sat, ivec2(a.x, b.y)), bb = satEntry(sat, ivec2(b.x, b.y));
    SatEntry cb = satEntry(sat, ivec2(c.x, b.y)), db = satEntry(sat, ivec2(d.x, b.y));
    SatEntry ac = satEntry(sat, ivec2(a.x, c.y)), bc = satEntry(sat, ivec2(b.x, c.y));
    SatEntry cc = satEntry(sat, ivec2(c.x, c.y)), dc = satEntry(sat, ivec2(d.x, c.y));
    SatEntry ad = satEntry(sat, ivec2(a.x, d.y)), bd = satEntry(sat, ivec2(b.x, d.y));
    SatEntry cd = satEntry(sat, ivec2(c.x, d.y)), dd = satEntry(sat, ivec2(d.x, d.y));

    // rows (y): main [c − a], high strip [d − c], low strip [b − a]
    // columns (x): the same with the x entries
    vec4 mm = satDD(cc, ac, ca, aa);            // x main,  y main
    vec4 hm = satDD(dc, cc, da, ca);            // x high,  y main
    vec4 lm = satDD(bc, ac, ba, aa);            // x low,   y main
    vec4 mh = satDD(cd, ad, cc, ac);            // x main,  y high
    vec4 hh = satDD(dd, cd, dc, cc);
    vec4 lh = satDD(bd, ad, bc, ac);
    vec4 ml = satDD(cb, ab, ca, aa);            // x main,  y low
    vec4 hl = satDD(db, cb, da, ca);
    vec4 ll = satDD(bb, ab, ba, aa);

    vec4 rowMain = mm + f1.x * hm - f0.x * lm;
    vec4 rowHigh = mh + f1.x * hh - f0.x * lh;
    vec4 rowLow  = ml + f1.x * hl - f0.x * ll;
    vec4 sum = rowMain + f1.y * rowHigh - f0.y * rowLow;
    return max(sum / area, vec4(0.0));
}

// float satKernelTexels(sampler2D sat, vec2 center, float searchTexels, float zr,
//                       vec2 depthRange, float lightTexels, bool perspective, vec2 kernelRange)
//   The width, in map texels, of the box the lighting pass filters this pixel with, when the
//   scene asks for a per-pixel kernel (filter "kernel": "per-pixel"): the penumbra that the
//   blockers in front of the receiver cast, sharp where they touch it, wide far away.
//   sat          the table, as for satBoxAverage
//   center       the receiver's position in the map, texel units
//   searchTexels the width of the box to search for blockers in (the framework's choice: the
//                penumbra a blocker at the near plane would cast, clamped)
//   zr           the receiver's relative depth (the scene's depth bias already subtracted)
//   depthRange   (near, far): relative depth z lies at world depth near + z·(far − near)
//                along the light's axis
//   lightTexels  the light's size in map texels at the receiver: perspective (spot) lights,
//                the emitter's width; orthographic (directional) ones, per world unit of
//                blocker–receiver distance
//   perspective  true for a spot light
//   kernelRange  (smallest, largest) box the result is clamped to
//   returns      the penumbra width w in texels, clamped to kernelRange; kernelRange.x where
//                nothing lies in front of the receiver
//
// Stub value: until implemented, it returns -1; the lighting pass then hatches the pixel in
// magenta and the renderer names this function. A correct solution never returns less
// than kernelRange.x.

float satKernelTexels(sampler2D sat, vec2 center, float searchTexels, float zr, vec2 depthRange,
                      float lightTexels, bool perspective, vec2 kernelRange)
{
    // 1. Blocker search: mean and variance of the depths in the search box (in double).
    vec4 avg = satBoxAverage(sat, center, vec2(searchTexels));
    double mu = double(avg.x);
    double variance = max(double(avg.y) - mu * mu, 1.0e-7LF);
    double z = double(zr);
    if (z <= mu)
        return kernelRange.x;                   // nothing in front of the receiver

    // 2. Chebyshev: p = share at or behind the receiver, s = 1 - p the blockers' share.
    double d = z - mu;
    double s = (d * d) / (variance + d * d);
    if (s < 1.0e-6LF)
        return kernelRange.x;

    // 3. mu = p·zr + s·z_b  =>  z_b = (mu - p·zr) / s = mu - variance / (zr - mu); clamped.
    double zb = clamp(mu - variance / d, 0.0LF, z);

    // 4. Penumbra by similar triangles, world depths along the light's axis.
    double near = double(depthRange.x), far = double(depthRange.y);
    double dr = near + z * (far - near);
    double db = near + zb * (far - near);
    double w = perspective ? double(lightTexels) * (dr - db) / max(db, 1.0e-4LF * far)
                           : double(lightTexels) * (dr - db);

    // 5. Fade in over the first 5 % of blockers' share.
    double wc = clamp(w, double(kernelRange.x), double(kernelRange.y));
    double t = clamp(s / 0.05LF, 0.0LF, 1.0LF);
    return float(mix(double(kernelRange.x), wc, t));
}
