// copy.comp: copies one RGBA32F image into another. The floor that a filter pass is measured
// against in `shadowlab bench`: a pass that reads and writes every texel once.
layout(local_size_x = 64, local_size_y = 1) in;

layout(binding = 0, rgba32f) uniform readonly image2D uSource;
layout(binding = 1, rgba32f) uniform writeonly image2D uDestination;
uniform ivec2 uImageSize;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, uImageSize))) return;
    imageStore(uDestination, p, imageLoad(uSource, p));
}
