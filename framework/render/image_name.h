// ImageName: the name of one image a render makes, as a value. A render's images are keyed by
// these names (RenderResult::images, the files <name>.exr, the goldens' manifest, the worker's
// <name>.raw): "final", "shadow", "relative_depth" and a further camera's "final_<camera>"; a light's maps
// "moments_raw", "moments_filtered", "sat", "second_depth", with "_light<i>" for a light other
// than the first shadowing one, "_cascade<c>" and "_layer<k>"; the grader's "msm_<image>" (the
// msm stage's lighting-only render), the depth ladder "moments_raw_depth_ladder" and the
// per-pixel SAT box ladder "moments_filtered_kernel". Names are
// built by str() and read by parse(), never by string prefixes.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace sl {

enum class ImageKind {
    Final, Shadow, MomentsRaw, MomentsFiltered, Sat, SecondDepth, DepthLadder, SatKernel,
    RelativeDepth  // a camera's zf toward the first shadowing light (the msm stage's input)
};

struct ImageName {
    ImageKind kind = ImageKind::Final;
    std::string camera{};  // Final, Shadow, RelativeDepth: "" for the first camera, else its name
    int light = -1;      // maps: -1 for the first shadowing light, else the light's index
    int cascade = 0;     // maps: 0, or the cascade
    int layer = 0;       // maps: 0, or the layer of a map with several (CSM)
    bool msmIsolated = false;  // "msm_": the msm stage's render from given filtered moments

    std::string str() const;
    // nullopt for a name no render makes.
    static std::optional<ImageName> parse(std::string_view name);

    // A camera's colour image: shown and compared in sRGB.
    bool colour() const { return kind == ImageKind::Final; }
    // A light's moment map or the depth ladder: stored at full float precision.
    bool moments() const {
        return kind == ImageKind::MomentsRaw || kind == ImageKind::MomentsFiltered ||
               kind == ImageKind::DepthLadder || kind == ImageKind::SatKernel;
    }
};

// "final", "shadow", "moments_raw", "moments_filtered", "sat", "second_depth",
// "moments_raw_depth_ladder", "moments_filtered_kernel", "relative_depth".
const char* toString(ImageKind);

// Whether `name` parses as a render's own image of kind `kind` (an msm_ image is not).
bool isImage(std::string_view name, ImageKind kind);

}  // namespace sl
