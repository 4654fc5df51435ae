// probe_check: reads each probe's pixel (probes count rows from the top, images are stored
// bottom row first) and compares it with the expected G within the probe's tolerance.
#include "probe_check.h"

#include <cmath>
#include <cstdio>

namespace sl {

std::string probeImageName(const Scene& scene, const ShadowProbe& probe) {
    if (scene.cameras.empty() || probe.camera == scene.cameras.front().name) return "shadow";
    return "shadow_" + probe.camera;
}

std::vector<std::string> probeFailures(
    const Scene& scene, const std::function<const Image*(const std::string&)>& image,
    const std::string& solution) {
    std::vector<std::string> failures;
    for (size_t i = 0; i < scene.probes.size(); ++i) {
        const ShadowProbe& p = scene.probes[i];
        const std::string where = scene.path + ": /expect/probes/" + std::to_string(i) + ": ";
        const Image* img = image(probeImageName(scene, p));
        char head[160];
        std::snprintf(head, sizeof head, "expected G = %.3g ± %.3g at pixel (%d, %d) of camera \"%s\"",
                      p.shadow, p.tolerance, p.pixel.x, p.pixel.y, p.camera.c_str());
        if (!img || img->empty()) {
            failures.push_back(where + head + ", but the render has no image " +
                               probeImageName(scene, p));
            continue;
        }
        if (p.pixel.x < 0 || p.pixel.y < 0 || p.pixel.x >= img->width || p.pixel.y >= img->height) {
            failures.push_back(where + head + ", but the image is only " +
                               std::to_string(img->width) + " × " + std::to_string(img->height));
            continue;
        }
        const float g = img->at(p.pixel.x, img->height - 1 - p.pixel.y, 0);
        if (std::isfinite(g) && std::fabs(g - p.shadow) <= p.tolerance) continue;
        char found[96];
        std::snprintf(found, sizeof found, " renders %.4f (off by %.3g)", g, std::fabs(g - p.shadow));
        const std::string who = solution == "reference" ? ", the reference" : ", " + solution;
        failures.push_back(where + head + who + found + "; why: \"" + p.why +
                           "\" (find the pixel of a world point with: shadowlab project --scene " +
                           scene.path + " --point x,y,z)");
    }
    return failures;
}

}  // namespace sl
