// techniques/sat_resolve.comp: the framework's filtered map from its double-float SAT. At every
// texel centre it evaluates boxAverage (common.glsl) with the scene's kernel, the very function
// the lighting pass reads the table with, and stores it in the map's own format. An output for
// inspection and study (moments_filtered); the lighting pass never reads it.
//   uShadowMaps[0], [1]: one layer's hi and lo tables; uDestination: that layer's filtered map.
layout(local_size_x = 8, local_size_y = 8) in;
#define SL_FILTER_SAT
#include "techniques/common.glsl"

layout(binding = 0, SL_MAP_FORMAT) uniform writeonly image2D uDestination;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, ivec2(uMapTexels)))) return;
    imageStore(uDestination, p, boxAverage(0, 0, vec2(p) + 0.5, vec2(uSatKernel)));
}
