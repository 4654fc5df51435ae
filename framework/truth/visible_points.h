// VisiblePoints: what each pixel of a camera sees, read back from the rasteriser itself
// (scene.vert + shaders/world_position.frag, the lighting pass's camera and depth test), so
// that the ray-traced truth and the rendered shadow image talk about the same surface points.
#pragma once

#include "image.h"
#include "renderer.h"
#include "scene.h"

namespace sl {

struct VisiblePoints {
    int width = 0, height = 0;
    Image position;         // RGBA: world xyz, w = 1 where geometry covers the pixel, else 0
    Image shadingNormal;    // RGBA: the interpolated vertex normal (what lighting.frag uses)
    Image geometricNormal;  // RGBA: the flat normal of the triangle seen
    bool covered(int x, int y) const { return position.at(x, y, 3) > 0.5f; }
};

// Rasterises the scene for camera `cameraIndex` on the current GL context. Rows bottom first,
// like every Image.
VisiblePoints renderVisiblePoints(const Scene& scene, const ShaderLibrary& library,
                                  int cameraIndex = 0);

}  // namespace sl
