// scene_truth: the ray-traced truth of a scene's first shadowing light as seen by a camera,
// cached on disk by scene hash (the SHA-256 of the scene file, its mesh files, the sample count
// and the truth's version), and the truth files written next to a render.
#pragma once

#include "image.h"
#include "ray_truth.h"
#include "scene.h"
#include "shader_source.h"
#include "visible_points.h"

#include <filesystem>
#include <string>

namespace sl {

namespace fs = std::filesystem;

struct SceneTruthOptions {
    RayTruthOptions rays;
    int camera = 0;
    fs::path cacheDir;  // empty: no cache
};

struct SceneTruth {
    VisiblePoints points;  // always rasterised afresh (cheap); the truth is what is cached
    RayTruth ray;
    std::string hash;      // hex SHA-256 the cache is keyed by
    bool fromCache = false;
    double seconds = 0.0;  // spent on this call
};

// The cache key of a scene's truth.
std::string sceneTruthHash(const Scene& scene, const SceneTruthOptions& options);

// Needs a current GL context (for the visible points). Throws if no light casts shadows.
SceneTruth computeSceneTruth(const Scene& scene, const ShaderLibrary& library,
                             const SceneTruthOptions& options);

// truth.exr: channels (R) G, (G) standard error, (B) 1 where the light reaches; truth.png: G.
void writeTruthFiles(const SceneTruth& truth, const fs::path& outDir);

// The default cache folder: $SHADOWLAB_CACHE, else $XDG_CACHE_HOME/shadowlab, else
// ~/.cache/shadowlab; the truth lives in its "truth" subfolder.
fs::path defaultTruthCache();

}  // namespace sl
