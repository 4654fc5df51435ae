// widen.comp: copies a map of another format (msm4-16bit's RGBA16) into RGBA32F, the format the
// filter stages (gaussian_blur.comp, sat.comp) read and write. texelFetch returns the stored
// UNORM16 values k / 65535 as floats, exactly as the lighting pass would read them.
layout(local_size_x = 64, local_size_y = 1) in;

uniform sampler2D uSource;
layout(binding = 1, rgba32f) uniform writeonly image2D uDestination;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, textureSize(uSource, 0)))) return;
    imageStore(uDestination, p, texelFetch(uSource, p, 0));
}
