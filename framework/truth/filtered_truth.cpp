// filtered_truth: same-kernel PCF of a shadow map in double (see filtered_truth.h).
#include "filtered_truth.h"

#include "light_view.h"
#include "mesh.h"
#include "renderer.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace sl {
namespace {

// One axis of the kernel as (texel index, weight) taps, indices already clamped or clipped.
struct Tap { int index; double weight; };

std::vector<Tap> axisTaps(double coord, int n, const FilterKernel& k,
                          const std::vector<double>& gauss) {
    std::vector<Tap> taps;
    if (k.kind == FilterKind::Sat) {  // box in texel units, clipped to [0, n]
        const double lo = std::clamp(coord - 0.5 * k.boxTexels, 0.0, double(n));
        const double hi = std::clamp(coord + 0.5 * k.boxTexels, 0.0, double(n));
        if (hi <= lo) return taps;
        for (int i = int(std::floor(lo)); i < int(std::ceil(hi)) && i < n; ++i) {
            const double cover = std::min(hi, i + 1.0) - std::max(lo, double(i));
            if (cover > 0) taps.push_back({i, cover / (hi - lo)});
        }
        return taps;
    }
    // Bilinear fetch (GL_LINEAR, clamp to edge) of the Gaussian-filtered map.
    const double s = coord - 0.5;
    const int i0 = int(std::floor(s));
    const double f = s - i0;
    const int r = int(gauss.size()) - 1;
    for (int b = 0; b < 2; ++b) {
        const double wb = b == 0 ? 1.0 - f : f;
        if (wb == 0.0) continue;
        const int centre = std::clamp(i0 + b, 0, n - 1);
        for (int a = -r; a <= r; ++a)
            taps.push_back({std::clamp(centre + a, 0, n - 1), wb * gauss[size_t(std::abs(a))]});
    }
    return taps;
}

std::vector<double> gaussOf(const FilterKernel& k) {
    if (k.kind != FilterKind::Gaussian || k.radius <= 0) return {1.0};
    // The renderer's own normalisation (float weights, as the GPU sees them), held in double.
    std::vector<double> out;
    for (float w : Renderer::gaussianWeights(k.radius, k.sigma)) out.push_back(w);
    return out;
}

double filtered(const Image& depth, glm::dvec2 uv, double zf, const FilterKernel& k,
                const std::vector<double>& gauss, const ReceiverPlane* plane) {
    const auto tx = axisTaps(uv.x * depth.width, depth.width, k, gauss);
    const auto ty = axisTaps(uv.y * depth.height, depth.height, k, gauss);
    double g = 0.0;
    for (const Tap& b : ty) {
        double row = 0.0;
        for (const Tap& a : tx) {
            const double z = plane ? plane->depthAt({(a.index + 0.5) / depth.width,
                                                     (b.index + 0.5) / depth.height})
                                   : zf;
            if (double(depth.at(a.index, b.index, 0)) < z) row += a.weight;
        }
        g += b.weight * row;
    }
    return g;
}

// How far a rasterised map depth may sit from the exact plane depth at the texel centre
// (float interpolation, the face normal from derivatives), in relative depth. A receiver-plane
// comparison without it is a coin toss on flat receivers with no depth bias.
double depthTolerance() {
    static const double tol = [] {
        const char* e = std::getenv("SHADOWLAB_TRUTH_TOLERANCE");  // for measuring it only
        return e ? std::atof(e) : 2e-5;
    }();
    return tol;
}

}  // namespace

double ReceiverPlane::depthAt(glm::dvec2 uv) const {
    // The light ray through uv: the points of NDC depth -1 and 1 (works for a perspective and
    // an orthographic light alike), met with the plane.
    const glm::dvec2 ndc = uv * 2.0 - 1.0;
    const glm::dvec4 a4 = inverseViewProjection * glm::dvec4(ndc, -1.0, 1.0);
    const glm::dvec4 b4 = inverseViewProjection * glm::dvec4(ndc, 1.0, 1.0);
    const glm::dvec3 a = glm::dvec3(a4) / a4.w, d = glm::dvec3(b4) / b4.w - a;
    const double denom = glm::dot(normal, d);
    if (std::abs(denom) < 1e-12 * glm::length(d)) return fallback;
    const glm::dvec3 x = a + (glm::dot(normal, point - a) / denom) * d;
    const double lightDepth = glm::dot(x - eye, forward);
    return std::clamp((lightDepth - range.x) / (range.y - range.x), 0.0, 1.0) - depthBias;
}

FilterKernel kernelOf(const ShadowEffect& fx) {
    FilterKernel k;
    k.kind = fx.filter;
    k.radius = fx.gaussianRadius;
    k.sigma = fx.gaussianSigma;
    k.boxTexels = fx.satKernelTexels;
    return k;
}

double filteredShadow(const Image& depth, glm::dvec2 uv, double zf, const FilterKernel& kernel,
                      const ReceiverPlane* plane) {
    return filtered(depth, uv, zf, kernel, gaussOf(kernel), plane);
}

Image filteredTruth(const Scene& scene, const VisiblePoints& points, const Image& reached,
                    int lightIndex, const Image& depth, const FilterKernel& kernel) {
    std::vector<Bounds> bounds;
    for (const Object& o : scene.objects) bounds.push_back(worldBounds(buildMesh(o, scene), objectToWorld(o)));
    const LightView view = computeLightView(scene.lights.at(size_t(lightIndex)), scene.shadow, bounds);
    const glm::dmat4 vp(view.viewProjection);
    const glm::dmat4 inverseVp = glm::inverse(vp);
    const glm::dvec3 eye(view.eye), forward(view.forward);
    const glm::dvec2 range(view.depthRange);
    const std::vector<double> gauss = gaussOf(kernel);
    Image g(points.width, points.height, 1);
    for (int y = 0; y < points.height; ++y)
        for (int x = 0; x < points.width; ++x) {
            if (reached.at(x, y, 0) < 0.5f) continue;
            const glm::dvec3 p(points.position.at(x, y, 0), points.position.at(x, y, 1),
                               points.position.at(x, y, 2));
            const glm::dvec4 clip = vp * glm::dvec4(p, 1.0);
            const glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
            if (clip.w <= 0.0 || std::abs(ndc.x) > 1.0 || std::abs(ndc.y) > 1.0) continue;
            const double lightDepth = glm::dot(p - eye, forward);
            const double zf = std::clamp((lightDepth - range.x) / (range.y - range.x), 0.0, 1.0) -
                              double(scene.shadow.depthBias);
            ReceiverPlane plane;
            plane.inverseViewProjection = inverseVp;
            plane.point = p;
            plane.normal = glm::dvec3(points.geometricNormal.at(x, y, 0),
                                      points.geometricNormal.at(x, y, 1),
                                      points.geometricNormal.at(x, y, 2));
            plane.eye = eye, plane.forward = forward, plane.range = range;
            plane.depthBias = double(scene.shadow.depthBias) + depthTolerance();
            plane.fallback = zf;
            const bool flat = glm::dot(plane.normal, plane.normal) > 0.5;
            g.at(x, y, 0) = float(filtered(depth, glm::dvec2(ndc) * 0.5 + 0.5, zf, kernel, gauss,
                                           flat ? &plane : nullptr));
        }
    return g;
}

}  // namespace sl
