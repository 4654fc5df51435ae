// scene_truth: cached ray-traced truth of a scene (see scene_truth.h).
#include "scene_truth.h"

#include <cstdio>

#include "image_io.h"
#include "light_reach.h"
#include "ray_scene.h"


#include <chrono>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace sl {
namespace {

// Bump when the truth's definition changes, so stale cache entries are never read
// (2: a directional light's size is an angle).
constexpr const char* kTruthVersion = "truth-2";

std::string fileBytes(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

}  // namespace

std::string sceneTruthHash(const Scene& scene, const SceneTruthOptions& options) {
    std::string key = std::string(kTruthVersion) + "\n" + fileBytes(scene.path);
    for (const Object& o : scene.objects)
        if (o.shape == ShapeType::Mesh) key += "\n" + fileBytes(o.meshPath);
    key += "\nsamples=" + std::to_string(stratifiedSide(options.rays.samples));
    // A study may give a light another size than its file (the light-size axis).
    for (const Light& l : scene.lights)
        key += "\nlight size=" + std::to_string(l.size) + "," + std::to_string(l.rectangle.x) +
               "," + std::to_string(l.rectangle.y);
    // ... and another place (the study's turning light, study_flicker.h): exact floats.
    char at[200];
    for (const Light& l : scene.lights) {
        std::snprintf(at, sizeof at, "\nlight at=%a,%a,%a to %a,%a,%a", l.position.x, l.position.y,
                      l.position.z, l.target.x, l.target.y, l.target.z);
        key += at;
    }
    const Camera& cam = scene.cameras.at(size_t(options.camera));
    key += "\ncamera=" + std::to_string(options.camera) + ":" + std::to_string(cam.width) + "x" +
           std::to_string(cam.height);  // a study may render the scene smaller than its file
    return sha256Hex(key);
}

fs::path defaultTruthCache() {
    if (const char* c = std::getenv("SHADOWLAB_CACHE"); c && *c) return fs::path(c) / "truth";
    if (const char* x = std::getenv("XDG_CACHE_HOME"); x && *x)
        return fs::path(x) / "shadowlab" / "truth";
    if (const char* h = std::getenv("HOME"); h && *h)
        return fs::path(h) / ".cache" / "shadowlab" / "truth";
    return fs::temp_directory_path() / "shadowlab" / "truth";
}

SceneTruth computeSceneTruth(const Scene& scene, const ShaderLibrary& library,
                             const SceneTruthOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    const int light = firstShadowingLight(scene);
    if (light < 0) throw std::runtime_error(scene.path + ": no light casts shadows: no truth");
    SceneTruth t;
    t.points = renderVisiblePoints(scene, library, options.camera);
    t.hash = sceneTruthHash(scene, options);
    const fs::path cached = options.cacheDir.empty() ? fs::path()
                                                     : options.cacheDir / (t.hash + ".exr");
    if (!cached.empty() && fs::exists(cached)) {
        const Image img = readImage(cached);
        if (img.width == t.points.width && img.height == t.points.height && img.channels == 3) {
            t.ray.light = light;
            t.ray.samplesPerPixel =
                scene.lights[size_t(light)].size > 0 ? stratifiedSide(options.rays.samples) *
                                                           stratifiedSide(options.rays.samples)
                                                     : 1;
            t.ray.shadow = Image(img.width, img.height, 1);
            t.ray.stdError = Image(img.width, img.height, 1);
            t.ray.reached = Image(img.width, img.height, 1);
            for (size_t i = 0, n = size_t(img.width) * img.height; i < n; ++i) {
                t.ray.shadow.pixels[i] = img.pixels[3 * i];
                t.ray.stdError.pixels[i] = img.pixels[3 * i + 1];
                t.ray.reached.pixels[i] = img.pixels[3 * i + 2];
                t.ray.maxStdError = std::max(t.ray.maxStdError, double(img.pixels[3 * i + 1]));
            }
            t.fromCache = true;
        }
    }
    if (!t.fromCache) {
        RayScene rays(scene);
        t.ray = traceRayTruth(scene, rays, t.points, light, options.camera, options.rays);
        if (!cached.empty()) {
            fs::create_directories(options.cacheDir);
            writeTruthFiles(t, options.cacheDir / ("tmp-" + t.hash));
            fs::rename(options.cacheDir / ("tmp-" + t.hash) / "truth.exr", cached);
            fs::remove_all(options.cacheDir / ("tmp-" + t.hash));
        }
    }
    t.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return t;
}

void writeTruthFiles(const SceneTruth& truth, const fs::path& outDir) {
    fs::create_directories(outDir);
    const RayTruth& r = truth.ray;
    Image packed(r.shadow.width, r.shadow.height, 3);
    for (size_t i = 0, n = r.shadow.pixels.size(); i < n; ++i) {
        packed.pixels[3 * i] = r.shadow.pixels[i];
        packed.pixels[3 * i + 1] = r.stdError.pixels[i];
        packed.pixels[3 * i + 2] = r.reached.pixels[i];
    }
    writeExr(packed, outDir / "truth.exr");
    writePngPreview(r.shadow, outDir / "truth.png", false);
}

}  // namespace sl
