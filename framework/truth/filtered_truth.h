// filtered_truth: the second reference, the exact filtered visibility. It is percentage-closer
// filtering of the same shadow map with the same kernel the technique filters its map with,
// in double: G = Σ_t K(t) · [z_t < z_f(t)] over shadow-map texels t, where z_f(t) is the depth
// of the receiver's own plane where texel t's light ray meets it, minus the depth bias
// (receiver-plane comparison: a flat receiver never shadows itself, so the reference has no
// acne, and the acne a technique shows is counted as its error). A technique's distance from
// it is its reconstruction error (light leaks, moment bounds); the distance between it and the
// ray-traced truth is the map's own error (resolution, bias, the kernel's blur).
//   gaussian: the moment filter's separable weights (Renderer::gaussianWeights, clamp to edge)
//             followed by the lighting pass's bilinear fetch, combined into one kernel;
//   box:      the SAT's box of `boxTexels` centred at the sample, clipped to the map, partly
//             covered texels weighted by the fraction covered (sat_lookup.glsl);
//   none:     the bilinear fetch alone.
#pragma once

#include "image.h"
#include "scene.h"
#include "visible_points.h"

#include <glm/glm.hpp>

#include <vector>

namespace sl {

struct FilterKernel {
    FilterKind kind = FilterKind::None;
    int radius = 0;          // gaussian
    float sigma = 0.0f;      // gaussian; <= 0: radius / 2
    float boxTexels = 1.0f;  // sat
};

// The kernel a scene's shadow effect filters with.
FilterKernel kernelOf(const ShadowEffect& effect);

// The receiver's plane as the light sees it: the relative depth of the plane along the light
// ray through light-space uv, minus the depth bias. Null: the fragment's one depth everywhere.
struct ReceiverPlane {
    glm::dmat4 inverseViewProjection{1.0};  // of the light
    glm::dvec3 point{0.0}, normal{0.0};     // the plane, world space
    glm::dvec3 eye{0.0}, forward{0.0};
    glm::dvec2 range{0.0, 1.0};
    double depthBias = 0.0;
    double fallback = 0.0;  // where the ray misses the plane: the fragment's own zf
    double depthAt(glm::dvec2 uv) const;
};

// Exact filtered visibility at one sample: `depth` holds the relative depth z of each texel
// in channel 0 (e.g. a moment map's b1), rows bottom first as GL reads them; `uv` in [0, 1]²;
// `zf` the fragment's relative depth after the depth bias, used for every texel unless a
// receiver `plane` gives each texel its own.
double filteredShadow(const Image& depth, glm::dvec2 uv, double zf, const FilterKernel& kernel,
                      const ReceiverPlane* plane = nullptr);

// The exact filtered G for every pixel of `reached` (elsewhere 0), from the pixels' visible
// points and face normals (the receiver planes), the light's view of the scene and the shadow
// map `depth` it rendered. Outside the light's frustum G = 0, as lighting.frag has it.
Image filteredTruth(const Scene& scene, const VisiblePoints& points, const Image& reached,
                    int lightIndex, const Image& depth, const FilterKernel& kernel);

}  // namespace sl
