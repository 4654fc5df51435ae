// sat_kernel_ladder: see sat_kernel_ladder.h.
#include "sat_kernel_ladder.h"

#include "cascades.h"
#include "light_view.h"
#include "probe.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace sl {

Image satKernelLadder(const ShaderLibrary& library, const Scene& scene, const Image& rawMoments) {
    const ShadowEffect& fx = scene.shadow;
    const Light* light = nullptr;
    for (const Light& l : scene.lights)
        if (l.castsShadows) { light = &l; break; }
    if (!light) throw std::invalid_argument("sat kernel ladder: the scene has no shadowing light");
    const LightView view = computeLightView(*light, fx, sceneBounds(scene));
    const glm::vec2 range = view.depthRange;
    const bool spot = light->type == LightType::Spot;
    const int n = rawMoments.width;
    // The lighting pass's frustum width (scene_passes.cpp): spot × depth, directional as is.
    const float frustum = spot ? 2.0f * std::tan(glm::radians(light->coneDegrees * 0.5f))
                               : 2.0f * light->extent;
    const int cells = std::min(n, 128);
    std::vector<SatKernelCase> cases;
    for (int y = 0; y < cells; ++y)
        for (int x = 0; x < cells; ++x) {
            const auto [tx, ty] = satKernelCellTexel(x, y, cells, n);
            const float surface = rawMoments.at(tx, ty, 0);
            for (float z : {surface, 1.0f}) {
                SatKernelCase c;
                c.center = {tx + 0.5f, ty + 0.5f};
                c.zr = z - fx.depthBias;
                c.depthRange = range;
                const float dr = range.x + c.zr * (range.y - range.x);
                const float texelWorld = (spot ? frustum * dr : frustum) / float(n);
                // As msm4.glsl: search as wide as a near-plane blocker's penumbra.
                const float nearPenumbra = spot ? light->size * (dr - range.x) / range.x
                                                : light->size * (dr - range.x);
                c.searchTexels = std::clamp(nearPenumbra / texelWorld, 1.0f, fx.satKernelTexels);
                c.lightTexels = light->size / texelWorld;
                c.perspective = spot;
                c.kernelRange = {1.0f, fx.satMaxKernelTexels};
                cases.push_back(c);
            }
        }
    const std::vector<float> w = probeSatKernelTexels(library, rawMoments, cases);
    Image out(cells, cells, 2);
    for (size_t i = 0; i < w.size(); ++i) out.pixels[i] = w[i];
    return out;
}

}  // namespace sl
