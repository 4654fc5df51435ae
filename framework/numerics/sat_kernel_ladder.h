// sat_kernel_ladder: what the grader's sat stage checks of satKernelTexels on a per-pixel
// scene. The shadow a kernel makes is no measure of it: 4MSM turns the last digits of a
// correct table into G up to 1 apart (two correct SAT pairs differ by more than 0.02 on 2 % of
// contact's pixels), so the stage compares the kernels themselves. Over a grid of the first
// shadowing light's map, two receivers per cell: the lit surface the map holds there (its
// depth less the scene's bias), and a receiver at the far end of the depth range, behind every
// caster; each with the search box, light size and limits the lighting pass would hand it.
#pragma once

#include "image.h"
#include "scene.h"
#include "shader_source.h"

namespace sl {

// The image name (one texel per grid cell; R: the lit surface's kernel, G: the far receiver's,
// both in texels).
inline constexpr const char* kSatKernelImage = "moments_filtered_kernel";

// The grader passes a width within the rubric's sat_kernel_abs + sat_kernel_rel · the
// reference's width (grader/rubric.json; why those values: docs/grading.md).

// The map texel a cell of the ladder's grid samples (`cells` per side, over a map `mapSize`
// texels wide): the texel at the cell's centre, from the bottom-left.
inline glm::ivec2 satKernelCellTexel(int x, int y, int cells, int mapSize) {
    const int step = mapSize / (cells > 0 ? cells : 1);
    return {x * step + step / 2, y * step + step / 2};
}

// The widths as a picture: each divided by `largest` (the reference's widest), R the lit
// surface's, G the far receiver's (a PNG of the widths themselves, 1 to 64, is white).
inline Image satKernelPreview(const Image& widths, float largest) {
    Image p(widths.width, widths.height, 3);
    const float scale = largest > 0.0f ? 1.0f / largest : 1.0f;
    for (size_t i = 0, n = size_t(widths.width) * widths.height; i < n; ++i)
        for (int c = 0; c < 2 && c < widths.channels; ++c)
            p.pixels[i * 3 + c] = widths.pixels[i * widths.channels + c] * scale;
    return p;
}

// The widest width of a kernel image (its preview's scale).
inline float satKernelLargest(const Image& widths) {
    float m = 0.0f;
    for (float w : widths.pixels) m = w > m ? w : m;
    return m;
}

// satKernelTexels of `library` over `rawMoments` (the light's moment map, as the shadow pass
// stores it) for the scene's first shadowing light, on a grid of at most 128 × 128 cells.
Image satKernelLadder(const ShaderLibrary& library, const Scene& scene, const Image& rawMoments);

}  // namespace sl
