// scene_size: a scene rendered smaller for a quick look (`shadowlab report --size`, and the
// demo's comparison sheets): its cameras, its shadow map and its filter widths scale together,
// so that shadows keep their softness in world units and a small image looks like a big one.
#pragma once

#include "scene.h"

namespace sl {

// Scales every camera so that the first one is `size` pixels wide (aspect kept), the shadow
// map by the same factor (at least 64 texels), the SAT box and the Gaussian radius and σ by the
// map's factor (at least one texel). The scene's probes name pixels of the full-size image, so
// they are dropped. A `size` equal to the first camera's width changes nothing.
void scaleScene(Scene& scene, int size);

// The width of the demo's comparison sheets (`./kit demo` passes `compare --size 256`), and of
// the reference images that stand in on them for the rows the student kit leaves out.
constexpr int kSheetImageWidth = 256;

}  // namespace sl::cli
