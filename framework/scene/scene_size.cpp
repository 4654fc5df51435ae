// scene_size: see scene_size.h.
#include "scene_size.h"

#include <algorithm>
#include <cmath>

namespace sl {

void scaleScene(Scene& scene, int size) {
    if (scene.cameras.empty() || size == scene.cameras[0].width) return;
    const double f = double(size) / scene.cameras[0].width;
    for (Camera& cam : scene.cameras) {
        cam.width = std::max(1, int(std::lround(cam.width * f)));
        cam.height = std::max(1, int(std::lround(cam.height * f)));
    }
    scene.probes.clear();
    ShadowEffect& fx = scene.shadow;
    const int map = std::max(64, int(std::lround(fx.mapSize * f)));
    const double g = double(map) / fx.mapSize;
    fx.mapSize = map;
    fx.satKernelTexels = float(std::max(1.0, fx.satKernelTexels * g));
    fx.satMaxKernelTexels = float(std::max(1.0, fx.satMaxKernelTexels * g));
    fx.gaussianRadius = std::max(1, int(std::lround(fx.gaussianRadius * g)));
    fx.gaussianSigma = float(fx.gaussianSigma * g);
}

}  // namespace sl
