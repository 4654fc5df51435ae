// Renderer's programs: which files and permutation each pass kind compiles, built on first use.
#include "render_internal.h"
#include "renderer.h"

#include <stdexcept>

namespace sl {

using render_detail::imageFormat;

// GLSL image format qualifier of a texture format (render_internal.h).
std::string render_detail::imageFormat(GLenum format) {
    switch (format) {
        case GL_R32F: return "r32f";
        case GL_RG32F: return "rg32f";
        case GL_RGBA32F: return "rgba32f";
        case GL_RGBA16: return "rgba16";
    }
    throw std::logic_error("no image format for texture format " + std::to_string(format));
}

GlProgram& Renderer::program(const std::string& first, const std::string& fragment,
                             const std::vector<std::string>& defines) {
    std::string key = first + "|" + fragment;
    for (const auto& d : defines) key += "|" + d;
    auto& slot = programs_[key];
    if (!slot) {
        slot = std::make_unique<GlProgram>(
            fragment.empty() ? GlProgram::compute(library_, first, defines)
                             : GlProgram::graphics(library_, first, fragment, defines));
    }
    return *slot;
}

GlProgram& Renderer::passProgram(PassKind kind, int blurRadius,
                                 const std::vector<std::string>& defines) {
    switch (kind) {
        case PassKind::Shadow: return program("scene.vert", "shadow_moments.frag", defines);
        case PassKind::GaussianX:
        case PassKind::GaussianY:
            // The radius is a compile-time constant (one program per radius): llvmpipe then
            // unrolls the taps and keeps the window in registers (docs/performance.md).
            return program("gaussian_blur.comp", "",
                           {"SL_BLUR_RADIUS=" + std::to_string(blurRadius)});
        case PassKind::SatRows:
        case PassKind::SatColumns: return program("sat.comp", "", {});
        case PassKind::SatResolve: return program("sat_resolve.comp", "", {});
        case PassKind::Lighting: return program("scene.vert", "lighting.frag", defines);
        case PassKind::ShadowSecond: break;  // framework techniques only (techniqueProgram)
    }
    throw std::logic_error("no program for this pass");
}

GlProgram& Renderer::techniqueProgram(PassKind kind, bool studentStages, unsigned mapFormat,
                                      const std::vector<std::string>& defines) {
    if (studentStages || kind == PassKind::Lighting) return passProgram(kind, 0, defines);
    const std::string format = "SL_MAP_FORMAT=" + imageFormat(mapFormat);
    switch (kind) {
        case PassKind::Shadow: return program("scene.vert", "techniques/store.frag", defines);
        case PassKind::ShadowSecond:
            return program("scene.vert", "techniques/second_depth_peel.frag", defines);
        case PassKind::GaussianX:
        case PassKind::GaussianY: return program("techniques/filter_gaussian.comp", "", {format});
        case PassKind::SatResolve: return program("techniques/sat_resolve.comp", "", {format});
        case PassKind::SatRows:
        case PassKind::SatColumns: {
            // The table's own format: float32 with the map's channel count.
            const GLenum sat = mapFormat == GL_RGBA16 ? GL_RGBA32F : GLenum(mapFormat);
            std::vector<std::string> d = {format, "SL_SAT_FORMAT=" + imageFormat(sat)};
            if (kind == PassKind::SatColumns) d.push_back("SL_SAT_COLUMNS");
            return program("techniques/filter_sat.comp", "", d);
        }
        default: break;
    }
    throw std::logic_error(std::string("no framework program for pass ") + toString(kind));
}

}  // namespace sl
