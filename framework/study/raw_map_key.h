// raw_map_key: when may two rows of the study share one light's raw shadow map? When the
// shadow pass would draw the same texels: the same scene and light, the same map size and
// format, the same shadow-pass program and the same values of the uniforms that program reads.
// The key says exactly that, and errs on the side of not sharing:
//   - the program is the shadow pass's own (scene.vert + techniques/store.frag, with the
//     solution's moments.glsl where the row stores moments; see render/pass_programs.cpp),
//     assembled by the ShaderLibrary with the plan's defines; its text is reduced to the lines
//     the preprocessor may compile (a `#ifdef SL_FILTER_SAT` in a block the pass never
//     compiles does not split it), and every define and technique parameter whose name that
//     text mentions is in the key with its value (EVSM's exponents, CSM's terms, ...);
//   - the clear values of each layer (technique.h shadowClearValues), the map's format and
//     layer count, its size and the light;
//   - the scene (a digest the caller gives: the study uses the truth's scene hash) — the light's
//     view depends on the scene and the light only (scene/light_view.cpp).
// Techniques with a second (peeling) shadow pass are never shared: their map has two parts.
#pragma once

#include "pass_plan.h"
#include "scene.h"
#include "shader_source.h"

#include <string>

namespace sl {

struct RawMapKey {
    std::string digest;  // hex SHA-256 of everything below; empty: never shared
    std::string label;   // for people: "depth R32F 1024² L0 3fa2c1d09b7e"
    std::string text;    // what the digest is of (for --explain and the tests)
    bool shareable() const { return !digest.empty(); }
};

// Assembles the shadow pass's program (throws ShaderError as a render would).
RawMapKey rawMapKey(const Scene& scene, const PassPlan& plan, int light,
                    const ShaderLibrary& library, const std::string& sceneDigest);

}  // namespace sl
