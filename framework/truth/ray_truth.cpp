// ray_truth: shadow rays from the rasteriser's visible points (see ray_truth.h).
#include "ray_truth.h"

#include "light_reach.h"
#include "ray_scene.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <thread>
#include <vector>

namespace sl {
namespace {

constexpr float kPi = 3.14159265358979323846f;

// SplitMix64: a fixed, portable hash, so the jitter (and the bytes of truth.exr) never depend
// on a library's random engine.
std::uint64_t mix(std::uint64_t z) {
    z += 0x9e3779b97f4a7c15ull;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}
float unitFloat(std::uint64_t h) { return float(h >> 40) * (1.0f / 16777216.0f); }

// An orthonormal frame (u, v) across the light's axis.
void emitterFrame(const Light& light, glm::vec3& u, glm::vec3& v) {
    const glm::vec3 f = glm::normalize(light.target - light.position);
    const glm::vec3 a = std::abs(f.y) < 0.99f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    u = glm::normalize(glm::cross(f, a));
    v = glm::cross(u, f);
}

}  // namespace

int stratifiedSide(int samples) {
    int m = int(std::lround(std::sqrt(double(std::max(samples, 4)))));
    if (m % 2) m += (m * m < samples) ? 1 : -1;  // even, for the paired variance estimate
    return std::max(m, 2);
}

glm::vec3 emitterSample(const Light& light, int i, int j, int m, float u, float v) {
    glm::vec3 eu, ev;
    emitterFrame(light, eu, ev);
    const float sx = 2.0f * (float(i) + u) / float(m) - 1.0f;  // [-1, 1]²
    const float sy = 2.0f * (float(j) + v) / float(m) - 1.0f;
    glm::vec2 q;
    if (light.rectangle.x > 0.0f) {
        q = {sx * 0.5f * light.rectangle.x, sy * 0.5f * light.rectangle.y};
    } else {  // concentric map of the square onto the disk of radius size / 2
        float r, phi;
        if (sx == 0.0f && sy == 0.0f) r = 0.0f, phi = 0.0f;
        else if (std::abs(sx) > std::abs(sy)) r = sx, phi = (kPi / 4.0f) * (sy / sx);
        else r = sy, phi = (kPi / 2.0f) - (kPi / 4.0f) * (sx / sy);
        r *= 0.5f * light.size;
        q = {r * std::cos(phi), r * std::sin(phi)};
    }
    // A directional light's size is an angle (radians), as the soft-shadow techniques read it
    // (penumbra = size · blocker-to-receiver distance): its emitter, seen from the target, spans
    // that angle, so the disk is size · |position − target| wide where it stands.
    if (light.type == LightType::Directional) q *= glm::length(light.position - light.target);
    return light.position + q.x * eu + q.y * ev;
}

RayTruth traceRayTruth(const Scene& scene, const RayScene& rays, const VisiblePoints& points,
                       int lightIndex, int cameraIndex, const RayTruthOptions& options) {
    const Light& light = scene.lights.at(size_t(lightIndex));
    const Camera& cam = scene.cameras.at(size_t(cameraIndex));
    const bool area = light.size > 0.0f;
    const bool directional = light.type == LightType::Directional;
    const int m = area ? stratifiedSide(options.samples) : 1;
    RayTruth t;
    t.light = lightIndex;
    t.samplesPerPixel = m * m;
    t.reached = lightReachMask(scene, points, lightIndex, cameraIndex);
    t.shadow = Image(points.width, points.height, 1);
    t.stdError = Image(points.width, points.height, 1);
    // Ray origins leave the surface along its face normal by a hair (1e-5 of the casters'
    // extent; the rasterised positions are within ~1e-6 relative of their triangle).
    const float offset = 1e-5f * std::max(rays.sceneDiagonal(), 1.0f);
    const float far = std::numeric_limits<float>::infinity();

    auto shadePixel = [&](int x, int y) {
        const glm::vec3 p(points.position.at(x, y, 0), points.position.at(x, y, 1),
                          points.position.at(x, y, 2));
        glm::vec3 ng(points.geometricNormal.at(x, y, 0), points.geometricNormal.at(x, y, 1),
                     points.geometricNormal.at(x, y, 2));
        if (glm::dot(ng, cam.position - p) < 0.0f) ng = -ng;  // the side the camera sees
        const glm::vec3 origin = p + offset * ng;
        const bool hasFace = glm::dot(ng, ng) > 0.5f;
        // Visible (1) or not (0) towards emitter point s (directional: along target -> s).
        auto visible = [&](const glm::vec3& s) -> int {
            glm::vec3 d = directional ? s - light.target : s - origin;
            const float len = glm::length(d);
            d /= len;
            if (hasFace && glm::dot(ng, d) <= 0.0f) return 0;  // the face itself hides it
            return rays.occluded(origin, d, 0.0f, directional ? far : len) ? 0 : 1;
        };
        if (!area) {
            t.shadow.at(x, y, 0) = float(1 - visible(light.position));
            return;
        }
        const std::uint64_t pixelKey = mix(std::uint64_t(y) * 65536u + std::uint64_t(x));
        int sum = 0, pairSquares = 0;
        for (int j = 0; j < m; ++j)
            for (int i = 0; i < m; i += 2) {  // horizontal pairs of strata
                int pair[2];
                for (int k = 0; k < 2; ++k) {
                    const std::uint64_t h = mix(pixelKey ^ (std::uint64_t(j * m + i + k) << 32));
                    pair[k] = visible(emitterSample(light, i + k, j, m, unitFloat(h),
                                                    unitFloat(mix(h))));
                }
                sum += pair[0] + pair[1];
                pairSquares += (pair[0] - pair[1]) * (pair[0] - pair[1]);
            }
        const double n = double(m) * m;
        t.shadow.at(x, y, 0) = float(1.0 - sum / n);
        // Collapsed-strata estimate (one sample per stratum, strata paired): Var ≈ Σ (y_a -
        // y_b)² / N². Conservative: a pair straddling a penumbra edge counts in full.
        t.stdError.at(x, y, 0) = float(std::sqrt(double(pairSquares)) / n);
    };

    const auto start = std::chrono::steady_clock::now();
    const int threads = options.threads > 0
                            ? options.threads
                            : int(std::max(1u, std::thread::hardware_concurrency()));
    std::vector<std::thread> pool;
    for (int k = 0; k < threads; ++k)
        pool.emplace_back([&, k] {
            for (int y = k; y < points.height; y += threads)  // rows interleaved: balanced
                for (int x = 0; x < points.width; ++x)
                    if (t.reached.at(x, y, 0) > 0.5f) shadePixel(x, y);
        });
    for (auto& th : pool) th.join();
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    size_t reachedCount = 0;
    for (float v : t.reached.pixels) reachedCount += v > 0.5f;
    t.raysPerSecond = seconds > 0 ? double(reachedCount) * t.samplesPerPixel / seconds : 0.0;
    for (float e : t.stdError.pixels) t.maxStdError = std::max(t.maxStdError, double(e));
    return t;
}

}  // namespace sl
