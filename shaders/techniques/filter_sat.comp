// techniques/filter_sat.comp: the summed-area table of the framework's techniques, as
// double-float pairs: sums run in double, and each is stored as hi = float(s), lo = float(s − hi)
// (≈ 48 significant bits), so box averages keep their digits at any map size without the tiled
// offsets of the student's sat.comp. One invocation owns a whole line (O(n) per line).
//   rows     (default): uSource (SL_MAP_FORMAT) -> (uHi, uLo), prefix sums along rows
//   columns  (SL_SAT_COLUMNS): (uHi, uLo) -> (uHi, uLo) in place, prefix sums along columns
layout(local_size_x = 1, local_size_y = 64) in;
#ifndef SL_SAT_COLUMNS
layout(binding = 0, SL_MAP_FORMAT) uniform readonly image2D uSource;
#endif
layout(binding = 1, SL_SAT_FORMAT) uniform image2D uHi;
layout(binding = 2, SL_SAT_FORMAT) uniform image2D uLo;
uniform ivec2 uImageSize;

void main() {
    int line = int(gl_GlobalInvocationID.y);
#ifdef SL_SAT_COLUMNS
    if (line >= uImageSize.x) return;
    int length = uImageSize.y;
#else
    if (line >= uImageSize.y) return;
    int length = uImageSize.x;
#endif
    dvec4 sum = dvec4(0.0);
    for (int i = 0; i < length; ++i) {
#ifdef SL_SAT_COLUMNS
        ivec2 p = ivec2(line, i);
        sum += dvec4(imageLoad(uHi, p)) + dvec4(imageLoad(uLo, p));
#else
        ivec2 p = ivec2(i, line);
        sum += dvec4(imageLoad(uSource, p));
#endif
        vec4 hi = vec4(sum);
        imageStore(uHi, p, hi);
        imageStore(uLo, p, vec4(sum - dvec4(hi)));
    }
}
