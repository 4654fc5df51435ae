// cli_project: `shadowlab project --scene S --point x,y,z` — where a world point lands in
// each camera's image (the pixel a probe names, y from the top) and in each light's shadow
// map, and whether the light sees it: for writing a scene's expect.probes (docs/scenes.md)
// without C++. The geometry is the renderer's own tessellation, intersected on the CPU
// (scene_rays.h); nothing is rendered.
#include "cli_commands.h"
#include "light_view.h"
#include "pass_plan.h"
#include "scene.h"
#include "scene_rays.h"

#include <glm/gtc/matrix_inverse.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <sstream>

namespace sl::cli {
namespace {

const char* kProjectHelp = R"(Projects world points through a scene's cameras and lights.

For each --point x,y,z and each camera: the pixel (x from the left, y from the TOP row, as
expect.probes writes it; the point's pixel is the one that contains it, rounded down) and
whether the camera sees the point or another surface in front of it. For each light: the
shadow-map texel (from the bottom-left, as GL stores it), the relative depth, and whether the
light sees the point (lit) or another object first (shadowed, by which). For the first
shadowing light (the one probes measure, G), the filter's footprint around the texel is
checked too: a probe is safe when every texel of it sees an occluder (G = 1 whatever the
filter) or none does (G = 0). Then a probe line to paste into the scene is printed.

Example:
  shadowlab project --scene scenes/classic.json --point -2.59,0,0.94)";

std::string num(double v, int digits = 4) {
    char b[48];
    std::snprintf(b, sizeof b, "%.*g", digits, std::fabs(v) < 1e-12 ? 0.0 : v);
    return b;
}

std::string vec(const glm::dvec3& p) { return "(" + num(p.x) + ", " + num(p.y) + ", " + num(p.z) + ")"; }

// The world ray through a light's shadow-map position (ndc x, y): origin on the near plane,
// direction to the far plane (t = 1 there).
void lightRay(const LightView& view, double nx, double ny, glm::dvec3& origin, glm::dvec3& dir) {
    const glm::dmat4 inv = glm::inverse(glm::dmat4(view.viewProjection));
    const glm::dvec4 a = inv * glm::dvec4(nx, ny, -1.0, 1.0), b = inv * glm::dvec4(nx, ny, 1.0, 1.0);
    origin = glm::dvec3(a) / a.w;
    dir = glm::dvec3(b) / b.w - origin;
}

struct Project {
    const Scene& scene;
    const SceneRays& rays;
    double eps;  // world distance below which two surfaces are the same

    std::string objectName(int k) const { return "\"" + scene.objects[size_t(k)].name + "\""; }

    void camera(const Camera& c, const glm::dvec3& p, std::ostream& out) const {
        const glm::dvec4 clip = glm::dmat4(computeCameraView(c).viewProjection) * glm::dvec4(p, 1.0);
        out << "  camera \"" << c.name << "\" (" << c.width << " x " << c.height << "): ";
        if (clip.w <= 0.0) {
            out << "the point is behind the camera\n";
            return;
        }
        const glm::vec2 px = projectToPixel(c, glm::vec3(p));
        const int x = int(std::floor(px.x)), y = int(std::floor(px.y));
        out << "pixel (" << x << ", " << y << ") from the top";
        if (x < 0 || y < 0 || x >= c.width || y >= c.height) out << ", outside the image";
        const glm::dvec3 o(c.position);
        const RayHit h = rays.first(o, p - o, 0.0, 1.0 - eps / glm::length(p - o), false);
        if (h.hit()) out << "; hidden: the camera sees " << objectName(h.object) << " in front of it";
        else out << "; visible";
        out << "\n";
    }

    // Prints the light's view of p; returns 1 (shadowed), 0 (lit) or -1 (unknown) for the
    // footprint verdict of the graded light.
    int light(size_t index, const LightView& view, bool graded, const glm::dvec3& p,
              std::ostream& out) const {
        const Light& l = scene.lights[index];
        const ShadowEffect& fx = scene.shadow;
        out << "  light " << index << " (" << toString(l.type);
        if (!l.castsShadows) {
            out << ", casts no shadows): lit: no shadow map, G = 0\n";
            return graded ? 0 : -1;
        }
        out << ", " << fx.mapSize << " x " << fx.mapSize << " shadow map, depth range ["
            << num(view.depthRange.x) << ", " << num(view.depthRange.y) << "])"
            << (graded ? ", the light probes measure" : "") << ":\n";
        const glm::dvec4 clip = glm::dmat4(view.viewProjection) * glm::dvec4(p, 1.0);
        const glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
        const double depth = glm::dot(p - glm::dvec3(view.eye), glm::dvec3(view.forward));
        const double rel = (depth - view.depthRange.x) / double(view.depthRange.y - view.depthRange.x);
        if (clip.w <= 0.0 || std::fabs(ndc.x) > 1.0 || std::fabs(ndc.y) > 1.0) {
            out << "    outside the light's shadow map: no probe here\n";
            return -1;
        }
        // Outside [near, far] the lighting pass clamps the relative depth (docs/scenes.md), and
        // the shadow pass clips casters there: only casters inside the range can shadow.
        const double nearD = view.depthRange.x, farD = view.depthRange.y;
        const double seen = std::clamp(depth, nearD, farD);
        auto inRange = [&](double d) { return d >= nearD && d <= farD; };
        const int N = fx.mapSize;
        const int tx = std::min(N - 1, int(std::floor((ndc.x * 0.5 + 0.5) * N)));
        const int ty = std::min(N - 1, int(std::floor((ndc.y * 0.5 + 0.5) * N)));
        out << "    texel (" << tx << ", " << ty << ") from the bottom-left, light depth "
            << num(depth) << ", relative depth " << num(rel, 6)
            << (rel < 0.0 || rel > 1.0 ? " (outside the depth range: clamped to " +
                                             num(std::clamp(rel, 0.0, 1.0)) + ")" : std::string())
            << "\n";
        // The light's own ray through p: an occluder before it, the receiver at it.
        glm::dvec3 o, d;
        lightRay(view, ndc.x, ndc.y, o, d);
        const double tp = glm::length(p - o) / glm::length(d);  // p = o + tp * d
        const double dt = eps / glm::length(d);
        const RayHit recv = rays.first(o, d, tp - dt, tp + dt, false);
        // The first caster before the point that the map holds (inside the depth range).
        RayHit occ;
        double od = 0.0;
        for (double t0 = 0.0;;) {
            const RayHit h = rays.first(o, d, t0, tp - dt, true);
            if (!h.hit()) break;
            od = glm::dot(o + h.t * d - glm::dvec3(view.eye), glm::dvec3(view.forward));
            if (inRange(od) && od < seen - eps) { occ = h; break; }
            t0 = h.t + 1e-9;
        }
        if (occ.hit()) {
            out << "    shadowed: the light sees " << objectName(occ.object) << " first, "
                << num(depth - od) << " nearer than the point\n";
        } else {
            out << "    lit: nothing between the light and the point"
                << (recv.hit() ? " (on " + objectName(recv.object) + ")" : " (on no surface)") << "\n";
        }
        if (!graded) return -1;
        // The filter's footprint (plus one texel for the bilinear lookup): texels whose first
        // surface is another object in front of the point.
        int h = 1;
        std::string filter = "no filter";
        if (fx.filter == FilterKind::Gaussian) {
            h = fx.gaussianRadius + 1;
            filter = "Gaussian radius " + std::to_string(fx.gaussianRadius);
        } else if (fx.filter == FilterKind::Sat) {
            h = int(std::ceil(fx.satKernelTexels / 2.0)) + 1;
            filter = "SAT box " + num(fx.satKernelTexels) + " texels";
        }
        int occluded = 0, total = 0;
        for (int y = ty - h; y <= ty + h; ++y)
            for (int x = tx - h; x <= tx + h; ++x) {
                if (x < 0 || y < 0 || x >= N || y >= N) continue;
                ++total;
                lightRay(view, (x + 0.5) / N * 2.0 - 1.0, (y + 0.5) / N * 2.0 - 1.0, o, d);
                const RayHit hit = rays.first(o, d, 0.0, 1e30, true);
                if (!hit.hit() || (recv.hit() && hit.object == recv.object)) continue;
                const double hd = glm::dot(o + hit.t * d - glm::dvec3(view.eye), glm::dvec3(view.forward));
                if (inRange(hd) && hd < seen - eps) ++occluded;
            }
        out << "    footprint (" << filter << ", " << 2 * h + 1 << " x " << 2 * h + 1
            << " texels with the bilinear lookup): " << occluded << " of " << total
            << " texels see an occluder in front of the point: ";
        if (occluded == total && occ.hit()) {
            out << "G = 1 whatever the filter (a safe probe)\n";
            return 1;
        }
        if (occluded == 0 && !occ.hit()) {
            out << "G = 0 whatever the filter (a safe probe)\n";
            return 0;
        }
        out << "a penumbra: G depends on the filter (not a probe)\n";
        return -1;
    }
};

}  // namespace

void addProjectCommand(CLI::App& app, Context& ctx) {
    auto* cmd = app.add_subcommand("project", "where a world point lands in each camera and light "
                                              "(for writing scene probes)");
    cmd->footer(kProjectHelp);
    struct Args {
        std::string scene;
        std::vector<std::string> points;
    };
    auto a = std::make_shared<Args>();
    cmd->add_option("--scene", a->scene, "scene file")->required();
    cmd->add_option("--point", a->points, "world point x,y,z (repeatable)")->required();
    cmd->callback([a, &ctx] {
        const Scene scene = loadScene(a->scene);
        const SceneRays rays(scene);
        Bounds all;
        for (const auto& b : rays.bounds())
            if (!b.empty()) all.add(b.lo), all.add(b.hi);
        const double eps = 1e-4 * (1.0 + glm::length(glm::dvec3(all.hi - all.lo)));
        const Project project{scene, rays, eps};
        const PassPlan plan = planPasses(scene);
        const int graded = plan.shadowLights.empty() ? -1 : plan.shadowLights.front();
        for (const std::string& text : a->points) {
            glm::dvec3 p;
            char tail = 0;
            if (std::sscanf(text.c_str(), "%lf,%lf,%lf%c", &p.x, &p.y, &p.z, &tail) != 3 ||
                !std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
                throw CLI::ValidationError("--point", "expected x,y,z (three numbers), found \"" + text + "\"");
            std::ostringstream out;
            out << scene.path << ", world point " << vec(p) << ":\n";
            for (const Camera& c : scene.cameras) project.camera(c, p, out);
            int verdict = -1;
            for (size_t i = 0; i < scene.lights.size(); ++i) {
                const LightView view = computeLightView(scene.lights[i], scene.shadow, rays.bounds());
                const int v = project.light(i, view, int(i) == graded, p, out);
                if (int(i) == graded) verdict = v;
            }
            if (scene.lights.empty() || graded < 0) verdict = 0;  // no shadow map: G = 0
            if (verdict >= 0) {
                const glm::vec2 px = projectToPixel(scene.cameras.front(), glm::vec3(p));
                out << "  probe: {\"pixel\": [" << int(std::floor(px.x)) << ", " << int(std::floor(px.y))
                    << "], \"shadow\": " << verdict << ".0, \"tolerance\": 0.05, \"why\": \"point "
                    << vec(p) << ": ...\"}\n";
            }
            std::cout << out.str();
        }
        ctx.exitCode = Ok;
    });
}

}  // namespace sl::cli
