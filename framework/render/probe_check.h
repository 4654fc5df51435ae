// probe_check: a scene's expect.probes (docs/scenes.md) against a render of the reference.
// A probe states the shadow intensity G its author worked out for one pixel; when the
// reference disagrees, the probe (or the scene) is wrong, and grading on it would be too.
#pragma once

#include "image.h"
#include "scene.h"

#include <functional>
#include <string>
#include <vector>

namespace sl {

// The image that holds a probe's pixel: "shadow" for the first camera, "shadow_<camera>"
// for the others (G of the first shadowing light).
std::string probeImageName(const Scene& scene, const ShadowProbe& probe);

// One line per probe that does not hold, naming the scene file, the probe's JSON path, the
// pixel, the expected and the value `solution` rendered ("reference", "student", ...) and the
// author's reasoning. `image(name)` returns the rendered image (bottom row first) or nullptr
// when there is none.
std::vector<std::string> probeFailures(const Scene& scene,
                                       const std::function<const Image*(const std::string&)>& image,
                                       const std::string& solution = "reference");

}  // namespace sl
