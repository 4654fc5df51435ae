// ray_truth: the physical ground truth. For every camera pixel a light reaches, the fraction of
// the light that is hidden from the pixel's visible point (G = 1 - visible fraction), traced
// with Embree through the same tessellated casters the shadow map rasterises.
//   point (size 0):  one shadow ray, exact hard visibility, standard error 0;
//   area (size > 0): N stratified rays to a disk of diameter `size` or a `rectangle`, centred
//                    on the light's position and facing along its axis; for a directional light
//                    the emitter sits at its position and is seen from its target, so every
//                    point gets the same cone of directions (a sun of that angular size).
#pragma once

#include "image.h"
#include "scene.h"
#include "visible_points.h"

#include <glm/glm.hpp>

#include <string>

namespace sl {

class RayScene;

struct RayTruthOptions {
    int samples = 1296;  // area lights: rounded to an even square m² (1296 = 36²), m >= 2
    int threads = 0;     // 0: std::thread::hardware_concurrency()
};

struct RayTruth {
    Image shadow;       // G, one channel; 0 where the light does not reach
    Image stdError;     // standard error of G per pixel (0 for point lights)
    Image reached;      // 1 where the light reaches the pixel (light_reach.h)
    int light = -1;
    int samplesPerPixel = 1;
    double maxStdError = 0.0;
    double raysPerSecond = 0.0;
};

// The sample grid side for a requested N: the even m with m² closest to N, at least 2.
int stratifiedSide(int samples);

// Points on the emitter for stratum (i, j) of an m × m grid, jittered by (u, v) in [0, 1)²:
// world position of the sample (disk through Shirley & Chiu's concentric map, area-preserving,
// so equal strata of the square are equal areas of the disk). A directional light's size is the
// emitter's angular diameter in radians seen from its target (docs/scenes.md).
glm::vec3 emitterSample(const Light& light, int i, int j, int m, float u, float v);

// Deterministic: the jitter is a hash of (pixel, stratum), so equal inputs give equal bytes at
// any thread count.
RayTruth traceRayTruth(const Scene& scene, const RayScene& rays, const VisiblePoints& points,
                       int lightIndex, int cameraIndex, const RayTruthOptions& options);

}  // namespace sl
