// study_flicker: see study_flicker.h.
#include "study_flicker.h"

#include <cmath>

namespace sl {

Scene movedLight(const Scene& scene, int frame, double stepDegrees) {
    Scene s = scene;
    const double a = frame * stepDegrees * M_PI / 180.0;
    const float c = float(std::cos(a)), sn = float(std::sin(a));
    for (Light& l : s.lights) {
        const glm::vec3 d = l.position - l.target;
        l.position = l.target + glm::vec3(c * d.x + sn * d.z, d.y, -sn * d.x + c * d.z);
    }
    return s;
}

double meanChange(const Image& a, const Image& b, const Image& ra, const Image& rb) {
    double sum = 0;
    size_t n = 0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            if (ra.at(x, y, 0) < 0.5f || rb.at(x, y, 0) < 0.5f) continue;
            const float ga = a.at(x, y, 0), gb = b.at(x, y, 0);
            // A non-finite G is a change as large as it gets.
            sum += std::isfinite(ga) && std::isfinite(gb) ? std::abs(double(ga) - gb) : 1.0;
            ++n;
        }
    return n ? sum / double(n) : 0.0;
}

FlickerSequence flickerSequence(const Scene& scene, int frames, double stepDegrees,
                                const ShaderLibrary& library, const SceneTruthOptions& options) {
    FlickerSequence q;
    q.frames = frames;
    q.stepDegrees = stepDegrees;
    for (int k = 0; k < frames; ++k)
        q.truths.push_back(computeSceneTruth(movedLight(scene, k, stepDegrees), library, options));
    for (int k = 1; k < frames; ++k)
        q.truthChange += meanChange(q.truths[size_t(k)].ray.shadow, q.truths[size_t(k - 1)].ray.shadow,
                                    q.truths[size_t(k)].ray.reached, q.truths[size_t(k - 1)].ray.reached);
    if (frames > 1) q.truthChange /= frames - 1;
    return q;
}

double rowChange(Renderer& renderer, const Scene& rowScene, const FlickerSequence& q,
                 const std::function<PassPlan(const Scene&)>& plan) {
    if (q.frames < 2) return 0.0;
    Image previous;
    double change = 0;
    for (int k = 0; k < q.frames; ++k) {
        const Scene s = movedLight(rowScene, k, q.stepDegrees);
        RenderInputs inputs;
        inputs.readMaps = false;  // G only
        RenderResult r = renderer.render(s, plan(s), inputs);
        Image g = std::move(r.images.at("shadow"));
        if (k > 0)
            change += meanChange(g, previous, q.truths[size_t(k)].ray.reached,
                                 q.truths[size_t(k - 1)].ray.reached);
        previous = std::move(g);
    }
    return change / (q.frames - 1);
}

}  // namespace sl
