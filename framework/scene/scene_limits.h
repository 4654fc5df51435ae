// The most the lighting pass takes, declared once: the loader refuses a scene over a limit
// (its file, key and the limit), the renderer sizes its uniform arrays by them, and GLSL gets
// them as the defines SL_MAX_LIGHTS, SL_MAX_CASCADES and SL_MAX_MAPS (limitDefines), never as
// numbers of its own.
#pragma once

#include <string>
#include <vector>

namespace sl {

inline constexpr int kMaxLights = 4;       // lights of a scene
inline constexpr int kMaxCascades = 4;     // cascades of one directional light
inline constexpr int kMaxShadowMaps = 16;  // textures lighting samples, all lights together

inline std::vector<std::string> limitDefines() {
    return {"SL_MAX_LIGHTS=" + std::to_string(kMaxLights),
            "SL_MAX_CASCADES=" + std::to_string(kMaxCascades),
            "SL_MAX_MAPS=" + std::to_string(kMaxShadowMaps)};
}

}  // namespace sl
