// copy_tile.comp: copies one RGBA32F image into another, T texels of a row per invocation: the
// register-tile shape of reference/gaussian_blur.comp without its taps. The second floor of
// `shadowlab bench` (framework/render/filter_benchmark.cpp): on llvmpipe the one-texel copy
// (copy.comp) is bound by the cost of running invocations and work groups, not by memory (a
// shader that loads and stores nothing costs half to two thirds of it), so a tiled filter can
// beat it; this copy is what a tiled filter is really up against.
// The defaults are the fastest shape measured on llvmpipe (2-core AMD EPYC, default, 128-bit
// vectors and one thread): T = 4 along x in 128 x 1 groups, 0.6-0.8 of copy.comp; T = 8 was
// 0.7-0.9, T = 16 1.0-1.3, T = 32 about 2; 8 x 8 groups and runs down columns were slower
// (notes: docs/performance.md). Defines, to study other shapes (filter_benchmark.cpp compiles
// the defaults and dispatches T along x):
//   SL_COPY_TEXELS  texels written per invocation (T, at most 32 so that Mesa unrolls the loop)
//   SL_COPY_ALONG_Y 1: the T texels run down a column; 0: along a row
//   SL_COPY_LOCAL_X, SL_COPY_LOCAL_Y  the work-group shape
#ifndef SL_COPY_TEXELS
#define SL_COPY_TEXELS 4
#endif
#ifndef SL_COPY_ALONG_Y
#define SL_COPY_ALONG_Y 0
#endif
#ifndef SL_COPY_LOCAL_X
#define SL_COPY_LOCAL_X 128
#endif
#ifndef SL_COPY_LOCAL_Y
#define SL_COPY_LOCAL_Y 1
#endif
layout(local_size_x = SL_COPY_LOCAL_X, local_size_y = SL_COPY_LOCAL_Y) in;

layout(binding = 0, rgba32f) uniform readonly image2D uSource;
layout(binding = 1, rgba32f) uniform writeonly image2D uDestination;
uniform ivec2 uImageSize;
uniform int uTexelsPerInvocation = SL_COPY_TEXELS;  // read back by the framework to size the dispatch

#if SL_COPY_ALONG_Y
const ivec2 kStep = ivec2(0, 1);
#else
const ivec2 kStep = ivec2(1, 0);
#endif

void main() {
    ivec2 g = ivec2(gl_GlobalInvocationID.xy);
    ivec2 first = g + g * kStep * (SL_COPY_TEXELS - 1);  // stretched by T along kStep
    // All loads, then all stores, as the reference's window: the loads are independent.
    vec4 texel[SL_COPY_TEXELS];
    for (int j = 0; j < SL_COPY_TEXELS; ++j)
        texel[j] = imageLoad(uSource, min(first + j * kStep, uImageSize - 1));
    for (int j = 0; j < SL_COPY_TEXELS; ++j) {
        ivec2 p = first + j * kStep;
        if (all(lessThan(p, uImageSize))) imageStore(uDestination, p, texel[j]);
    }
}
