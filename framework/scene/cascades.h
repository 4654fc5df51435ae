// cascades: cascaded shadow maps for a directional light. The first camera's view range is
// cut into n slices (uniform, logarithmic, or the "practical" blend of the two, Zhang et al.
// 2006), and each slice gets its own orthographic light view fitted around that slice of the
// camera frustum, so that near the camera one map texel covers little ground. planPasses
// decides the slices (PassPlan::cascades); the renderer fits the views.
#pragma once

#include "light_view.h"
#include "mesh.h"
#include "scene.h"

#include <glm/glm.hpp>

#include <vector>

namespace sl {

// The n + 1 view depths that bound the slices, d_0 = near .. d_n = far, i = 0..n:
//   uniform      d_i = near + (far − near)·i/n
//   logarithmic  d_i = near·(far/near)^(i/n)
//   practical    d_i = λ·logarithmic_i + (1 − λ)·uniform_i
std::vector<float> cascadeSplits(float nearDepth, float farDepth, int n, CascadeSplit scheme,
                                 float lambda);

// The camera view depths the cascades cover: [near, far] of `camera`, clipped to the depths
// the scene's objects occupy (no cascade is spent on empty space beyond the ground).
glm::vec2 cascadeRange(const Camera& camera, const std::vector<Bounds>& objectBounds);

// World bounds of every object, on the CPU (the meshes SceneGeometry uploads): what
// cascadeRange needs when there is no SceneGeometry (planning).
std::vector<Bounds> sceneBounds(const Scene& scene);

// The light view of one cascade: `whole` (the light's own view: same eye, direction and depth
// range, so relative depths agree between cascades) with its orthographic window re-fitted
// around the camera frustum slice [nearDepth, farDepth]: a square around the slice's bounding
// circle in the light's view plane (its size does not change as the camera turns), its centre
// snapped to whole texels (the texels stay put on the ground as the camera moves).
// `halfWidth`: the window's half-width, world units.
LightView fitCascade(const LightView& whole, const Camera& camera, float nearDepth,
                     float farDepth, int mapSize, float* halfWidth);

}  // namespace sl
