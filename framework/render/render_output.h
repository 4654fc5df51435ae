// render_output: writes a render's images (float EXR + PNG previews) and its JSON sidecar.
#pragma once

#include "gl_context.h"
#include "pass_plan.h"
#include "renderer.h"
#include "scene.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

namespace sl {

struct RenderMetadata {
    std::string solution;  // as given on the command line
    ContextInfo context;
};

// Writes <name>.exr for every image, PNG previews (moment maps as colour: RGB = b1, b2, b3;
// shadow as grey; final colour sRGB-encoded) and render.json: scene, solution, backend,
// renderer, Mesa version, technique (name, parameters, formats and bytes of every map), plan
// with per-pass times, SHA-256 of every file, stub notes.
// Returns the sidecar.
nlohmann::json writeRenderOutputs(const Scene& scene, const PassPlan& plan,
                                  const RenderResult& result, const RenderMetadata& meta,
                                  const std::filesystem::path& outDir);

}  // namespace sl
